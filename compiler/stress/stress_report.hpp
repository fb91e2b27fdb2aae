// How `matbricks stress` prints its results: a table for people, JSON records, the Markdown
// of docs/fp16.md, and for each worst input the exact command that replays it with `eval`.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "stress/stress_run.hpp"

namespace mb {

// `cli` is how to call matbricks, global options included ("matbricks --shaderlib DIR").
// The command writes the worst in-domain (or out-of-domain) row to <key>.worst.csv and runs
// eval on it; empty when there is no such row.
std::string replayCommand(const StressResult& r, const std::string& cli, bool inDomain);

nlohmann::json toJson(const StressResult& r, const std::string& cli);
std::string formatStressTable(const std::vector<StressResult>& results);
// The per-probe fp16 (or fp32) error table published as docs/fp16.md.
std::string formatStressMarkdown(const std::vector<StressResult>& results, const std::string& command,
                                 const std::string& device);

}  // namespace mb
