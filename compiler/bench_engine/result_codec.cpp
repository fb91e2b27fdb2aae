#include "bench_engine/result_codec.hpp"

#include "core/result_cache.hpp"

namespace mb::bench {

using nlohmann::json;

json cacheJson(const CostMeasurement& c) {
  return {{"ns_per_eval", jsonNumber(c.nsPerEval)},
          {"ns_per_eval_low", jsonNumber(c.nsPerEvalLow)},
          {"ns_per_eval_high", jsonNumber(c.nsPerEvalHigh)},
          {"confidence", jsonNumber(c.confidence)},
          {"resolved", c.resolved},
          {"ns_resolution", jsonNumber(c.nsResolution)},
          {"ns_baseline_spread", jsonNumber(c.nsBaselineSpread)},
          {"ns_raw", jsonNumber(c.nsRaw)},
          {"ns_baseline", jsonNumber(c.nsBaseline)},
          {"records", c.records},
          {"iterations", c.iterations},
          {"evaluations", c.evaluations},
          {"calibration_rounds", c.calibrationRounds},
          {"gpu_timestamps", c.gpuTimestamps}};
}

CostMeasurement costFromCache(const json& j) {
  CostMeasurement c;
  c.nsPerEval = numberFromJson(j.at("ns_per_eval"));
  c.nsPerEvalLow = numberFromJson(j.at("ns_per_eval_low"));
  c.nsPerEvalHigh = numberFromJson(j.at("ns_per_eval_high"));
  c.confidence = numberFromJson(j.at("confidence"));
  c.resolved = j.at("resolved").get<bool>();
  c.nsResolution = numberFromJson(j.at("ns_resolution"));
  c.nsBaselineSpread = numberFromJson(j.at("ns_baseline_spread"));
  c.nsRaw = numberFromJson(j.at("ns_raw"));
  c.nsBaseline = numberFromJson(j.at("ns_baseline"));
  c.records = j.at("records").get<uint64_t>();
  c.iterations = j.at("iterations").get<uint32_t>();
  c.evaluations = j.at("evaluations").get<uint64_t>();
  c.calibrationRounds = j.at("calibration_rounds").get<uint32_t>();
  c.gpuTimestamps = j.at("gpu_timestamps").get<bool>();
  return c;
}

json cacheJson(const BenchCost& c) {
  return {{"measured", cacheJson(c.measured)}, {"static", jsonNumber(c.staticCost)}};
}

BenchCost benchCostFromCache(const json& j) {
  return {costFromCache(j.at("measured")), numberFromJson(j.at("static"))};
}

json cacheJson(const ErrorSummary& e) {
  const ErrorSummary::State s = e.state();
  return {{"values", s.values},
          {"finite", s.finite},
          {"non_finite", s.nonFinite},
          {"truth_invalid", s.truthInvalid},
          {"max", {jsonNumber(s.maxAbs), jsonNumber(s.maxRel), jsonNumber(s.maxScaled)}},
          {"sum", {jsonNumber(s.sumAbs), jsonNumber(s.sumRel), jsonNumber(s.sumScaled)}}};
}

ErrorSummary errorSummaryFromCache(const json& j) {
  ErrorSummary::State s;
  s.values = j.at("values").get<uint64_t>();
  s.finite = j.at("finite").get<uint64_t>();
  s.nonFinite = j.at("non_finite").get<uint64_t>();
  s.truthInvalid = j.at("truth_invalid").get<uint64_t>();
  const json &max = j.at("max"), &sum = j.at("sum");
  s.maxAbs = numberFromJson(max.at(0));
  s.maxRel = numberFromJson(max.at(1));
  s.maxScaled = numberFromJson(max.at(2));
  s.sumAbs = numberFromJson(sum.at(0));
  s.sumRel = numberFromJson(sum.at(1));
  s.sumScaled = numberFromJson(sum.at(2));
  return ErrorSummary(s);
}

json cacheJson(const ErrorStats& s) {
  return {{"components", s.components},
          {"nan", s.nanCount},
          {"inf", s.infCount},
          {"negative", s.negativeCount},
          {"reference_invalid", s.referenceInvalid},
          {"failures", s.failures},
          {"max_abs", jsonNumber(s.maxAbs)},
          {"max_rel", jsonNumber(s.maxRel)},
          {"max_ulp", jsonNumber(s.maxUlp)},
          {"max_conditioning", jsonNumber(s.maxConditioning)},
          {"passed_by_conditioning", s.passedByConditioning},
          {"worst_ratio", jsonNumber(s.worstRatio)},
          {"worst_record", s.worstRecord}};
}

ErrorStats errorStatsFromCache(const json& j) {
  ErrorStats s;
  s.components = j.at("components").get<uint64_t>();
  s.nanCount = j.at("nan").get<uint64_t>();
  s.infCount = j.at("inf").get<uint64_t>();
  s.negativeCount = j.at("negative").get<uint64_t>();
  s.referenceInvalid = j.at("reference_invalid").get<uint64_t>();
  s.failures = j.at("failures").get<uint64_t>();
  s.maxAbs = numberFromJson(j.at("max_abs"));
  s.maxRel = numberFromJson(j.at("max_rel"));
  s.maxUlp = numberFromJson(j.at("max_ulp"));
  s.maxConditioning = numberFromJson(j.at("max_conditioning"));
  s.passedByConditioning = j.at("passed_by_conditioning").get<uint64_t>();
  s.worstRatio = numberFromJson(j.at("worst_ratio"));
  s.worstRecord = j.at("worst_record").get<int64_t>();
  return s;
}

json cacheJson(const BenchItem& it) {
  return {{"id", it.id},
          {"kind", it.kind},
          {"cost", cacheJson(it.cost)},
          {"static_cost", jsonNumber(it.staticCost)},
          {"spirv_instructions", it.spirvInstructions},
          {"yardstick", it.yardstick},
          {"ground_truth_bricks", it.groundTruthBricks},
          {"error", cacheJson(it.error)},
          {"vs_reference", cacheJson(it.vsReference)}};
}

BenchItem benchItemFromCache(const json& j) {
  BenchItem it;
  it.id = j.at("id").get<std::string>();
  it.kind = j.at("kind").get<std::string>();
  it.cost = costFromCache(j.at("cost"));
  it.staticCost = numberFromJson(j.at("static_cost"));
  it.spirvInstructions = j.at("spirv_instructions").get<size_t>();
  it.yardstick = j.at("yardstick").get<std::string>();
  it.groundTruthBricks = j.at("ground_truth_bricks").get<std::vector<std::string>>();
  it.error = errorSummaryFromCache(j.at("error"));
  it.vsReference = errorStatsFromCache(j.at("vs_reference"));
  return it;
}

}  // namespace mb::bench
