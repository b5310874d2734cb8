#include "bench/repeats.h"

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

namespace physdbg::bench {
namespace {

using Key = std::tuple<std::string, std::string, std::string, int>;  // name, n, threads, occurrence

double measure(const nlohmann::json& record) {
  const nlohmann::json& ratio = record.value("ratio", nlohmann::json());
  if (ratio.is_number()) return ratio.get<double>();
  const nlohmann::json& ours = record.value("ours_ms", nlohmann::json());
  return ours.is_number() ? ours.get<double>() : 0.0;
}

nlohmann::json listOf(const std::vector<const nlohmann::json*>& records, const char* field) {
  nlohmann::json list = nlohmann::json::array();
  for (const nlohmann::json* record : records) list.push_back(record->value(field, nlohmann::json()));
  return list;
}

nlohmann::json summarise(const std::vector<const nlohmann::json*>& records) {
  std::vector<const nlohmann::json*> sorted = records;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const nlohmann::json* a, const nlohmann::json* b) { return measure(*a) < measure(*b); });
  nlohmann::json result = *sorted[(sorted.size() - 1) / 2];
  result["repeats"] = records.size();
  result["ratio_runs"] = listOf(records, "ratio");
  result["ours_ms_runs"] = listOf(records, "ours_ms");
  const bool ratios = std::all_of(records.begin(), records.end(), [](const nlohmann::json* record) {
    return record->value("ratio", nlohmann::json()).is_number();
  });
  result["ratio_min"] = ratios ? nlohmann::json(measure(*sorted.front())) : nlohmann::json();
  result["ratio_max"] = ratios ? nlohmann::json(measure(*sorted.back())) : nlohmann::json();
  return result;
}

}  // namespace

std::vector<nlohmann::json> medianOfRuns(const std::vector<std::vector<nlohmann::json>>& runs) {
  std::map<Key, std::vector<const nlohmann::json*>> cases;
  std::vector<Key> order;
  for (const std::vector<nlohmann::json>& run : runs) {
    std::map<std::tuple<std::string, std::string, std::string>, int> seen;
    for (const nlohmann::json& record : run) {
      const auto field = [&record](const char* name) { return record.value(name, nlohmann::json()).dump(); };
      const auto triple = std::make_tuple(field("name"), field("n"), field("threads"));
      const Key key{std::get<0>(triple), std::get<1>(triple), std::get<2>(triple), seen[triple]++};
      auto [entry, added] = cases.try_emplace(key);
      if (added) order.push_back(key);
      entry->second.push_back(&record);
    }
  }
  std::vector<nlohmann::json> results;
  for (const Key& key : order) results.push_back(summarise(cases.at(key)));
  return results;
}

}  // namespace physdbg::bench
