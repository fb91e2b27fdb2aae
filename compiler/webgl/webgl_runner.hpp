// The page side of drawInBrowser (webgl_draw.hpp): a script that defines mbDraw(job) in a blank
// page. job is the DrawJob as JSON, every float or byte array base64 (little-endian); mbDraw
// returns {device, compileMs, renderMs, targets: [base64 RGBA32F per colour target]} or throws an
// Error whose message is one line.
#pragma once
#include <string>

namespace mb::webgl {

const std::string& webglRunnerScript();

}  // namespace mb::webgl
