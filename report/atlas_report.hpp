// Renderers of `tripack atlas`: a line per n (its best row), the builders below the
// best, the errors; JSON with every row; CSV = atlas.csv's table (jobs/atlas_files.hpp holds
// the files' format).
#pragma once

#include <iosfwd>

#include "jobs/atlas.hpp"

namespace tripack::report {

struct RenderOptions;  // report/render.hpp

// `tripack atlas`: a line per n (its best row), the builders that fell short, the errors.
void render_text(std::ostream& out, const jobs::AtlasResult& a, const RenderOptions& o);
void render_json(std::ostream& out, const jobs::AtlasResult& a, const RenderOptions& o);
void render_csv(std::ostream& out, const jobs::AtlasResult& a, const RenderOptions& o);

}  // namespace tripack::report
