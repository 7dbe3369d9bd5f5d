// Renderers of the campaign's and the database commands' results, one function per
// format like every other command's (report/render.hpp, whose render() dispatches to these; JSON
// conventions there: high-precision numbers as strings, `seconds`, errors as {"error": ...}):
//  * `tripack campaign`: CampaignReport (the run's counts and the best of every n in its range);
//  * `tripack db best`: jobs::BestTable;
//  * `tripack db check`: jobs::DbCheck;
//  * `tripack db import`: jobs::ImportResult;
//  * `tripack db prune`: jobs::PruneResult.
// `tripack db export` writes packing files (formats/formats.hpp), not a rendering.
#pragma once

#include <iosfwd>
#include <string>

#include "jobs/campaign.hpp"
#include "jobs/import.hpp"
#include "jobs/stored.hpp"

namespace tripack::report {

struct RenderOptions;  // report/render.hpp

// What `tripack campaign` prints: the request's range and the run's result, with the database's
// best packing of every n in the range, labelled (jobs::best_table).
struct CampaignReport {
  long long n_first = 0, n_last = 0;
  int runs = 0;  // seeds per n
  std::string db;
  jobs::CampaignResult result;
  jobs::BestTable best;
};

void render_text(std::ostream& out, const CampaignReport& r, const RenderOptions& o);
void render_json(std::ostream& out, const CampaignReport& r, const RenderOptions& o);
void render_csv(std::ostream& out, const CampaignReport& r, const RenderOptions& o);

void render_text(std::ostream& out, const jobs::BestTable& t, const RenderOptions& o);
void render_json(std::ostream& out, const jobs::BestTable& t, const RenderOptions& o);
void render_csv(std::ostream& out, const jobs::BestTable& t, const RenderOptions& o);

void render_text(std::ostream& out, const jobs::DbCheck& c, const RenderOptions& o);
void render_json(std::ostream& out, const jobs::DbCheck& c, const RenderOptions& o);
void render_csv(std::ostream& out, const jobs::DbCheck& c, const RenderOptions& o);

void render_text(std::ostream& out, const jobs::ImportResult& r, const RenderOptions& o);
void render_json(std::ostream& out, const jobs::ImportResult& r, const RenderOptions& o);
void render_csv(std::ostream& out, const jobs::ImportResult& r, const RenderOptions& o);

void render_text(std::ostream& out, const jobs::PruneResult& r, const RenderOptions& o);
void render_json(std::ostream& out, const jobs::PruneResult& r, const RenderOptions& o);
void render_csv(std::ostream& out, const jobs::PruneResult& r, const RenderOptions& o);

}  // namespace tripack::report
