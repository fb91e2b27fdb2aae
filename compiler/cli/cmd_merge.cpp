// matbricks merge SHARD_DIR... -o DIR: joins the N shard directories of one
// `compile --shard i/N` split into the package a single `compile` would write, byte for byte
// (docs/targets.md "Shards"). The inputs (scene or materials, options) come from the shards'
// shard.json and are read again from the working directory; every compile unit comes from a
// shard, none is compiled, and a missing or damaged one is an error naming the shard.
#include "cli/cli_common.hpp"
#include "cli/compile_run.hpp"

namespace mb::cli {
namespace {

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out;
  unsigned jobs = 0;
  bool quiet = false;
};

int runMerge(const MergeArgs& m, GlobalOptions& g) {
  std::vector<std::filesystem::path> dirs(m.shards.begin(), m.shards.end());
  const ShardSet shards = ShardSet::open(dirs);
  CompileArgs a;
  compileRequestFromJson(shards.command(), (dirs.front() / "shard.json").string(), a.request);
  a.request.out = m.out;
  a.request.jobs = m.jobs;
  a.request.quiet = m.quiet;
  std::vector<ProtectedPath> inputs;
  for (const auto& d : dirs) inputs.push_back({d, "shard directory"});
  return runCompile(a, g, &shards, inputs);
}

}  // namespace

Command addMergeCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<MergeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "Join the shard directories of one 'compile --shard i/N' split into its package (byte-identical)");
  cmd->add_option("shards", args->shards, "The N shard directories, in any order")->required();
  cmd->add_option("-o,--output", args->out,
                  "Package directory: created, filled when empty, or replaced atomically when it is a matbricks "
                  "package; anything else is refused")
      ->required();
  cmd->add_option("-j,--jobs", args->jobs, "Parallel jobs for reading and checking the shards' entries");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  return {cmd, [args, &g] { return runMerge(*args, g); }};
}

}  // namespace mb::cli
