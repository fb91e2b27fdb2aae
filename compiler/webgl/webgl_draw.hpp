// The webgl2 target run where it runs: WebGL 2.0 in headless Chromium (Debian's `chromium`:
// ANGLE over its SwiftShader Vulkan, no GPU needed), driven over the DevTools pipe
// (chromium_pipe.hpp). A DrawJob (glrun/draw_job.hpp) goes to a blank page as JSON with base64
// data; the page's runner (webgl_runner.cpp) compiles the ESSL 3.00 shaders, binds the blocks
// and samplers by name, draws into RGBA32F targets (EXT_color_buffer_float) and reads them back.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "glrun/draw_job.hpp"

namespace mb::webgl {

// No chromium, no WebGL 2.0 context or a missing extension, a shader the browser rejects (its
// first info-log line, naming the stage), a GL error, or a browser that did not answer. One line.
class WebglError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The chromium program: $MATBRICKS_CHROMIUM when set (WebglError if it is not executable), else
// `chromium` on PATH; "" when none.
std::string chromiumProgram();

// Draws each job as gl::drawOnGl does (the same state, targets and row order), in one browser
// started for the call; DrawResult::device is WebGL's unmasked renderer and version.
std::vector<gl::DrawResult> drawInBrowser(const std::vector<gl::DrawJob>& jobs);

}  // namespace mb::webgl
