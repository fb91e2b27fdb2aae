// bench's results as the result cache stores them (core/result_cache.hpp): every field, every
// double exact (non-finite ones included), so that a report built from cached entries shows
// the same numbers as the run that measured them. Readers throw (a std::exception) on a value
// of the wrong shape; the caller then measures again.
#pragma once
#include <nlohmann/json.hpp>

#include "bench_engine/bench_runner.hpp"

namespace mb::bench {

nlohmann::json cacheJson(const CostMeasurement& c);
CostMeasurement costFromCache(const nlohmann::json& j);

nlohmann::json cacheJson(const BenchCost& c);
BenchCost benchCostFromCache(const nlohmann::json& j);

nlohmann::json cacheJson(const ErrorSummary& e);
ErrorSummary errorSummaryFromCache(const nlohmann::json& j);

nlohmann::json cacheJson(const ErrorStats& s);
ErrorStats errorStatsFromCache(const nlohmann::json& j);

// A brick's or permutation's item, without its frontier marks (markFrontier sets them over
// the whole chart).
nlohmann::json cacheJson(const BenchItem& it);
BenchItem benchItemFromCache(const nlohmann::json& j);

}  // namespace mb::bench
