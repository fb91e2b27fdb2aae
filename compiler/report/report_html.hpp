// The report as files (docs/report.md): index.html with its style inline and no script, and
// the images it shows beside it (PNG previews and LUT, SVG charts), all by relative path, so
// the directory works from file:// with no network.
#pragma once
#include <map>
#include <string>

#include "report/report_data.hpp"

namespace mb::report {

// relative path -> bytes; "index.html" among them.
std::map<std::string, std::string> renderReport(const ReportData& report);

}  // namespace mb::report
