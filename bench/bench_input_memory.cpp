// Peak memory of the CLI against the size of its input (docs/formats.md "Input memory"): JSON
// and glTF inputs may cost at most 10 bytes per input byte beyond the command's own baseline,
// and `eval` streams its CSV (constant memory however many rows). Writes synthetic inputs into
// WORKDIR (nothing large is kept in git), runs the real CLI on each as a child process and
// reads the child's peak RSS from wait4(2).
//
//   mb_bench_input_memory MATBRICKS WORKDIR [EVAL_ROWS=1000000,10000000]   ("" runs no large eval)
//
// Inputs: a material JSON just under its 16 MiB limit in three shapes (one long description;
// an array of small numbers; small objects: the last two over a material's value limit), a
// ~40 MB glTF in four shapes (a buffer as a data: URI; a scene graph of nodes with matrices;
// nodes that are tiny objects, the worst case of a JSON tree; a .glb with a BIN chunk), the
// two node shapes also as `compile --scene` (which walks the nodes), and
// eval CSVs of the given row counts. Each is compared with the same command on a small input (the
// baseline: the process, the library, the compiler or the Vulkan device). Prints one JSON
// object per run. This process writes the inputs in small blocks and holds nothing large: a
// forked child's ru_maxrss includes its parent's at the fork.
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "child_run.hpp"

namespace fs = std::filesystem;

namespace {

constexpr uint64_t kMaterialBytes = (uint64_t{16} << 20) - 4096;  // just under the 16 MiB limit
constexpr uint64_t kGltfBytes = 40'000'000;

// The parts of a valid material JSON around a bulk field (the bulk is written in between).
const char* kMaterialHead =
    "{\n  \"name\": \"big\",\n  \"model\": \"standard\",\n  \"bricks\": {\"roughness\": \"roughness_clamped\", "
    "\"diffuse\": \"diffuse_lambert\", \"specular_d\": \"d_ggx\", \"specular_v\": \"v_smith_ggx_correlated\", "
    "\"fresnel\": \"f_schlick\"},\n  \"parameters\": {\"baseColor\": {\"type\": \"vec3\", \"default\": [0.2, 0.4, "
    "0.8]}},\n";
const char* kGltfMaterial =
    "\"asset\": {\"version\": \"2.0\"},\n  \"materials\": [{\"name\": \"big\", \"pbrMetallicRoughness\": "
    "{\"baseColorFactor\": [0.8, 0.2, 0.2, 1.0], \"metallicFactor\": 0.0, \"roughnessFactor\": 0.5}}]";

// Writes `head`, then `item(i)` for i = 0, 1, ... (joined by `sep`) while the file stays under
// `bytes` minus the tail, then `tail`.
uint64_t writeBulk(const fs::path& file, const std::string& head, const std::function<std::string(uint64_t)>& item,
                   const std::string& sep, const std::string& tail, uint64_t bytes) {
  std::ofstream out(file, std::ios::binary);
  out << head;
  uint64_t size = head.size();
  for (uint64_t i = 0;; ++i) {
    const std::string s = (i ? sep : "") + item(i);
    if (size + s.size() + tail.size() > bytes) break;
    out << s;
    size += s.size();
  }
  out << tail;
  return size + tail.size();
}

uint64_t writeMaterial(const fs::path& file, const std::string& shape) {
  const std::string head = kMaterialHead;
  if (shape == "description")
    return writeBulk(
        file, head + "  \"description\": \"", [](uint64_t) { return std::string("A long description. "); }, "",
        "\"\n}\n", kMaterialBytes);
  if (shape == "numbers")
    return writeBulk(
        file, head + "  \"x_numbers\": [", [](uint64_t) { return std::string("0.25"); }, ", ", "]\n}\n",
        kMaterialBytes);
  return writeBulk(
      file, head + "  \"x_objects\": {",
      [](uint64_t i) { return "\"p" + std::to_string(i) + "\": {\"type\": \"float\", \"default\": 0.5}"; }, ", ",
      "}\n}\n", kMaterialBytes);
}

void appendU32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
}

uint64_t writeGltf(const fs::path& file, const std::string& shape, uint64_t bytes) {
  // One mesh uses the material, and the first node that mesh: `compile --scene` compiles it.
  const std::string head =
      std::string("{\n  ") + kGltfMaterial + ",\n  \"meshes\": [{\"primitives\": [{\"material\": 0}]}]";
  if (shape == "small") {
    std::ofstream(file, std::ios::binary) << head << ",\n  \"nodes\": [{\"mesh\": 0}]\n}\n";
    return fs::file_size(file);
  }
  if (shape == "data_uri") {
    // One buffer of zeros, base64 ("AAAA" per 3 bytes), as an exporter embeds it.
    const uint64_t chars = (bytes - 400) / 4 * 4;
    return writeBulk(
        file,
        head + ",\n  \"buffers\": [{\"byteLength\": " + std::to_string(chars / 4 * 3) +
            ", \"uri\": \"data:application/octet-stream;base64,",
        [](uint64_t) { return std::string("AAAA"); }, "", "\"}]\n}\n", bytes);
  }
  if (shape == "nodes")
    return writeBulk(
        file, head + ",\n  \"nodes\": [",
        [](uint64_t i) {
          return "{" + std::string(i ? "" : "\"mesh\": 0, ") + "\"name\": \"node" + std::to_string(i) +
                 "\", \"matrix\": [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 12.5, 3.25, -7.75, "
                 "1.0]}";
        },
        ",\n    ", "]\n}\n", bytes);
  if (shape == "tiny_nodes")  // the worst shape for a JSON tree: one small object per ~20 bytes
    return writeBulk(
        file, head + ",\n  \"nodes\": [",
        [](uint64_t i) { return i ? "{\"name\": \"n" + std::to_string(i) + "\"}" : std::string("{\"mesh\": 0}"); },
        ", ", "]\n}\n", bytes);
  // .glb: the JSON chunk declares the BIN chunk as buffer 0 (glTF 2.0, "GLB-stored Buffer").
  const uint32_t binLength = static_cast<uint32_t>((bytes - 1024) / 4 * 4);
  std::string json =
      "{" + std::string(kGltfMaterial) + ", \"buffers\": [{\"byteLength\": " + std::to_string(binLength) + "}]}";
  while (json.size() % 4) json += ' ';
  std::string header;
  appendU32(header, 0x46546C67);
  appendU32(header, 2);
  appendU32(header, static_cast<uint32_t>(12 + 8 + json.size() + 8 + binLength));
  appendU32(header, static_cast<uint32_t>(json.size()));
  appendU32(header, 0x4E4F534A);
  std::ofstream out(file, std::ios::binary);
  out << header << json;
  std::string bin;
  appendU32(bin, binLength);
  appendU32(bin, 0x004E4942);
  out << bin;
  const std::string zeros(1 << 16, '\0');
  for (uint64_t left = binLength; left > 0;) {
    const uint64_t n = std::min<uint64_t>(left, zeros.size());
    out.write(zeros.data(), static_cast<std::streamsize>(n));
    left -= n;
  }
  out.close();
  return fs::file_size(file);
}

// d_ggx's inputs (n, v, l, alpha): the same few valid rows over and over.
uint64_t writeCsv(const fs::path& file, uint64_t rows) {
  std::ofstream out(file, std::ios::binary);
  out << "n.x,n.y,n.z,v.x,v.y,v.z,l.x,l.y,l.z,alpha\n";
  const char* kRows[] = {"0,0,1,0.6,0,0.8,-0.6,0,0.8,0.3\n", "0,0,1,0,0,1,0,0,1,0.05\n",
                         "0,0,1,0.8,0,0.6,0,0.6,0.8,0.7\n"};
  for (uint64_t i = 0; i < rows; ++i) out << kRows[i % 3];
  out.close();
  return fs::file_size(file);
}

using Run = mb::bench::ChildRun;

Run runChild(const std::vector<std::string>& args, const fs::path& log) {
  return mb::bench::runChild(args, log, "/dev/null");
}

void report(const std::string& name, const std::vector<std::string>& args, uint64_t inputBytes, const Run& r,
            const Run& baseline) {
  const double extraBytes = (r.peakRssKb - baseline.peakRssKb) * 1024.0;
  nlohmann::json j{{"input", name},
                   {"command", args.size() > 1 ? args[1] : ""},
                   {"input_bytes", inputBytes},
                   {"exit_status", WIFEXITED(r.status) ? WEXITSTATUS(r.status) : -1},
                   {"wall_s", r.wallS},
                   {"peak_rss_mb", r.peakRssKb / 1024.0},
                   {"baseline_peak_rss_mb", baseline.peakRssKb / 1024.0},
                   {"bytes_per_input_byte", inputBytes ? extraBytes / static_cast<double>(inputBytes) : 0.0}};
  std::printf("%s\n", j.dump().c_str());
  std::fflush(stdout);
}

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s MATBRICKS WORKDIR [EVAL_ROWS=1000000,10000000]\n", argv[0]);
    return 2;
  }
  const std::string cli = fs::absolute(argv[1]).string();
  const fs::path work = fs::absolute(argv[2]);
  const std::vector<std::string> evalRows = splitList(argc > 3 ? argv[3] : "1000000,10000000");
  fs::remove_all(work);
  fs::create_directories(work);
  // --no-cache: every run compiles its one permutation, the baseline as well (a cache hit for
  // one and a miss for the other would differ by the compiler's ~30 MB, not by the input).
  auto compile = [&](const fs::path& input) {
    fs::remove_all(work / "pkg");
    return std::vector<std::string>{cli, "compile", "-q", input.string(), "--no-cache", "-o", (work / "pkg").string()};
  };
  auto compileScene = [&](const fs::path& input) {
    fs::remove_all(work / "pkg");
    return std::vector<std::string>{
        cli, "compile", "-q", "--scene", input.string(), "--no-cache", "-o", (work / "pkg").string()};
  };

  // Materials: the baseline is the smallest valid material of the same shape.
  const fs::path small = work / "small.json";
  std::ofstream(small, std::ios::binary) << kMaterialHead << "  \"description\": \"small\"\n}\n";
  const Run materialBase = runChild(compile(small), work / "log.txt");
  report("material small", compile(small), fs::file_size(small), materialBase, materialBase);
  for (const char* shape : {"description", "numbers", "objects"}) {
    const fs::path file = work / (std::string("material_") + shape + ".json");
    const uint64_t bytes = writeMaterial(file, shape);
    report(std::string("material ") + shape, compile(file), bytes, runChild(compile(file), work / "log.txt"),
           materialBase);
    fs::remove(file);
  }

  const fs::path smallGltf = work / "small.gltf";
  writeGltf(smallGltf, "small", 0);
  const Run gltfBase = runChild(compile(smallGltf), work / "log.txt");
  report("gltf small", compile(smallGltf), fs::file_size(smallGltf), gltfBase, gltfBase);
  const Run sceneBase = runChild(compileScene(smallGltf), work / "log.txt");
  report("gltf scene small", compileScene(smallGltf), fs::file_size(smallGltf), sceneBase, sceneBase);
  for (const char* shape : {"data_uri", "nodes", "tiny_nodes", "glb"}) {
    const fs::path file = work / (std::string("big_") + shape + (std::string(shape) == "glb" ? ".glb" : ".gltf"));
    const uint64_t bytes = writeGltf(file, shape, kGltfBytes);
    report(std::string("gltf ") + shape, compile(file), bytes, runChild(compile(file), work / "log.txt"), gltfBase);
    // The scene walk reads the node graph that material import skips.
    if (std::string(shape) == "nodes" || std::string(shape) == "tiny_nodes")
      report(std::string("gltf scene ") + shape, compileScene(file), bytes,
             runChild(compileScene(file), work / "log.txt"), sceneBase);
    fs::remove(file);
  }

  // eval: stdout (a few lines per row) goes to /dev/null.
  auto eval = [&](const fs::path& csv) {
    return std::vector<std::string>{cli, "eval", "--brick", "d_ggx", "--input", csv.string()};
  };
  const fs::path smallCsv = work / "rows_10.csv";
  writeCsv(smallCsv, 10);
  const Run evalBase = runChild(eval(smallCsv), "/dev/null");
  report("eval 10 rows", eval(smallCsv), fs::file_size(smallCsv), evalBase, evalBase);
  for (const auto& rows : evalRows) {
    const fs::path csv = work / ("rows_" + rows + ".csv");
    const uint64_t bytes = writeCsv(csv, std::stoull(rows));
    report("eval " + rows + " rows", eval(csv), bytes, runChild(eval(csv), "/dev/null"), evalBase);
    fs::remove(csv);
  }
  fs::remove_all(work);
  return 0;
}
