// What the description forms share besides resolveMaterial (material_desc.hpp): resolving into
// a sink the form already reports into, so a file's syntax and meaning errors come out
// together, and the file-order sort every form reports in.
#pragma once
#include <string>
#include <vector>

#include "load/material_desc.hpp"

namespace mb {

// resolveMaterial without the throw: every problem goes to `sink`.
MaterialDesc resolveMaterialInto(const MaterialSource& source, const ShaderLibrary& lib, DiagnosticSink& sink);

// The end of every form's parse: resolves `source` into `sink` (which holds the form's own
// problems) and throws all of them in file order if there is an error.
MaterialDesc finishMaterial(const MaterialSource& source, const ShaderLibrary& lib, DiagnosticSink& sink);

// Throws DiagnosticError with `sink`'s diagnostics in file order if it holds an error: the
// material's own file first, then other files (includes, surface files) in the order they
// first appear; within a file by line and column.
void throwInFileOrder(const DiagnosticSink& sink, const std::string& mainFile);

// `text` for a message: at most 60 characters, so a megabyte-long token in a bad input makes a
// one-line diagnostic, not a megabyte one.
std::string clipped(const std::string& text);
// didYouMean, except for words too long to be a typo of anything (it is quadratic).
std::string suggest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace mb
