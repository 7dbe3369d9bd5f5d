#include "jobs/work_unit.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/io.hpp"

namespace tripack::jobs {

namespace {

constexpr int kDigits = 21;  // enough to give back a long double exactly

nlohmann::json encode_packing(const store::StoredPacking& p) {
  nlohmann::json points = nlohmann::json::array();
  for (const Vec2L& v : p.points)
    points.push_back({format_significant(v.x, kDigits), format_significant(v.y, kDigits)});
  nlohmann::json bonds = nlohmann::json::array();
  for (const Bond& b : p.bonds) bonds.push_back({b.a, b.b});
  return {{"n", p.n},
          {"d", p.d},
          {"graph_hash", p.graph_hash},
          {"points", points},
          {"bonds", bonds},
          {"rattlers", p.rattlers},
          {"certified", p.certified},
          {"first_seed", p.first_seed},
          {"tool_version", p.tool_version}};
}

store::StoredPacking decode_packing(const nlohmann::json& j) {
  store::StoredPacking p;
  p.n = j.at("n").get<long long>();
  p.d = j.at("d").get<std::string>();
  p.graph_hash = j.at("graph_hash").get<std::string>();
  for (const auto& xy : j.at("points"))
    p.points.push_back(
        Vec2L{std::stold(xy.at(0).get<std::string>()), std::stold(xy.at(1).get<std::string>())});
  for (const auto& b : j.at("bonds"))
    p.bonds.push_back(Bond{b.at(0).get<int>(), b.at(1).get<int>()});
  p.rattlers = j.at("rattlers").get<std::vector<int>>();
  p.certified = j.at("certified").get<bool>();
  p.first_seed = j.at("first_seed").get<std::uint64_t>();
  p.tool_version = j.at("tool_version").get<std::string>();
  return p;
}

}  // namespace

std::string encode_run(const store::RunRecord& run) {
  nlohmann::json j = {{"n", run.n},
                      {"seed", run.seed},
                      {"method", run.method},
                      {"outcome", run.outcome},
                      {"events", run.events},
                      {"seconds", run.seconds},
                      {"tool_version", run.tool_version}};
  if (run.packing) j["packing"] = encode_packing(*run.packing);
  // Outcomes carry exception texts: never let a stray byte make the dump throw.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

store::RunRecord decode_run(const std::string& text) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    store::RunRecord run;
    run.n = j.at("n").get<long long>();
    run.seed = j.at("seed").get<std::uint64_t>();
    run.method = j.at("method").get<std::string>();
    run.outcome = j.at("outcome").get<std::string>();
    run.events = j.at("events").get<long long>();
    run.seconds = j.at("seconds").get<double>();
    run.tool_version = j.at("tool_version").get<std::string>();
    if (j.contains("packing")) run.packing = decode_packing(j.at("packing"));
    return run;
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("a worker rank sent an unreadable run record: ") +
                             e.what());
  }
}

}  // namespace tripack::jobs
