// The description forms each input argument accepts, in one place: every subcommand's help
// text uses these strings, and tests/test_command_forms.cpp checks that docs/cli.md's table
// and each `--help` say the same (issue 17: they had drifted apart).
#pragma once

namespace mb::cli {

inline constexpr const char* kMaterialFilesHelp =
    "Material files: .json, .mat (macro form), .gltf/.glb (every material of the file)";
inline constexpr const char* kSceneFileHelp = "Scene file: .json (scene JSON), .gltf/.glb (glTF 2.0 scene)";

}  // namespace mb::cli
