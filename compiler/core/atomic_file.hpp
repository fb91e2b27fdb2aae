// Replacing one file so that concurrent readers never see it half written: the compile cache
// (compile/) and the environment cache (preview/) store entries this way. A file the user named
// goes through PackageWriter::writeFileAtomically (write/), which also cleans up after a kill.
#pragma once
#include <filesystem>
#include <string>

namespace mb {

// Writes `bytes` to a temporary sibling of `file` whose name no other writer uses (process id,
// thread id, a counter), then rename(2)s it over `file`: a reader sees the old file, the new
// one or none, never a partial one. False (and no temporary left) on any I/O failure. For
// matbricks' own cache directories; a file the user named goes through writeFileAtomically.
bool replaceFileAtomically(const std::filesystem::path& file, const std::string& bytes);

}  // namespace mb
