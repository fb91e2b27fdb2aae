#include "report/albedo_chart.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "bench_engine/report.hpp"
#include "bench_engine/svg_chart.hpp"

namespace mb::report {
namespace {

constexpr double kWidth = 560, kHeight = 360;
constexpr double kLeft = 64, kRight = 150, kTop = 48, kBottom = 52;  // margins
// Colour-blind-safe qualitative palette (Okabe and Ito, "Color Universal Design", 2002).
constexpr const char* kPalette[] = {"#0072b2", "#e69f00", "#009e73", "#cc79a7", "#d55e00", "#56b4e9", "#000000"};

struct Frame {
  double yMax;
  double px(double noV) const { return kLeft + noV * (kWidth - kLeft - kRight); }
  double py(double a) const { return kHeight - kBottom - a / yMax * (kHeight - kTop - kBottom); }
};

std::string num(double v) { return bench::printfDouble("%.4g", v); }

void drawFrame(std::ostringstream& s, const Frame& f) {
  const double left = kLeft, right = kWidth - kRight, top = kTop, bottom = kHeight - kBottom;
  s << "<g font-size=\"11\" stroke-width=\"1\">\n";
  for (double x = 0; x <= 1.0 + 1e-9; x += 0.2)
    s << "<line x1=\"" << f.px(x) << "\" y1=\"" << top << "\" x2=\"" << f.px(x) << "\" y2=\"" << bottom
      << "\" stroke=\"#e6e6e6\"/><text x=\"" << f.px(x) << "\" y=\"" << bottom + 16 << "\" text-anchor=\"middle\">"
      << bench::printfDouble("%g", x) << "</text>\n";
  double step = bench::niceStep(f.yMax);
  for (double y = 0; y <= f.yMax + 1e-9 * step; y += step)
    s << "<line x1=\"" << left << "\" y1=\"" << f.py(y) << "\" x2=\"" << right << "\" y2=\"" << f.py(y)
      << "\" stroke=\"#e6e6e6\"/><text x=\"" << left - 6 << "\" y=\"" << f.py(y) + 4 << "\" text-anchor=\"end\">"
      << bench::printfDouble("%g", y) << "</text>\n";
  s << "<line x1=\"" << left << "\" y1=\"" << f.py(1) << "\" x2=\"" << right << "\" y2=\"" << f.py(1)
    << "\" stroke=\"#888888\" stroke-dasharray=\"5 4\"/>\n"
    << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\"" << bottom - top
    << "\" fill=\"none\" stroke=\"#333333\"/>\n"
    << "<text x=\"" << (left + right) / 2 << "\" y=\"" << kHeight - 14 << "\" text-anchor=\"middle\">n·v</text>\n"
    << "<text transform=\"translate(18 " << (top + bottom) / 2
    << ") rotate(-90)\" text-anchor=\"middle\">directional albedo (F = 1)</text>\n</g>\n";
}

}  // namespace

std::string albedoSvg(const energy::LobeAlbedo& a, const energy::EnergyGrid& grid) {
  double maxA = 1.0;
  for (const auto& c : a.cells)
    if (std::isfinite(c.gpu)) maxA = std::max({maxA, c.gpu, c.reference});
  Frame f{maxA * 1.08};
  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
    << "\" viewBox=\"0 0 " << kWidth << " " << kHeight << "\" font-family=\"sans-serif\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << kLeft << "\" y=\"22\" font-size=\"14\" font-weight=\"bold\">" << bench::xmlEscape(a.lobe->name)
    << "</text>\n<text x=\"" << kLeft << "\" y=\"38\" font-size=\"11\" fill=\"#555555\">"
    << bench::xmlEscape(energy::lobeKindName(a.lobe->kind)) << " lobe; line: GPU, circles: double reference</text>\n";
  drawFrame(s, f);

  const size_t nR = grid.perceptualRoughness.size();
  for (size_t j = 0; j < nR; ++j) {
    const char* colour = kPalette[j % std::size(kPalette)];
    std::ostringstream line, marks;
    for (size_t i = 0; i * nR + j < a.cells.size(); ++i) {
      const energy::AlbedoCell& c = a.cells[i * nR + j];
      if (!std::isfinite(c.gpu)) continue;
      line << f.px(c.NoV) << "," << f.py(c.gpu) << " ";
      marks << "<circle cx=\"" << f.px(c.NoV) << "\" cy=\"" << f.py(c.reference)
            << "\" r=\"3.5\" fill=\"white\" stroke=\"" << colour << "\"><title>n·v " << num(c.NoV) << ", roughness "
            << num(c.perceptualRoughness) << ": GPU " << num(c.gpu) << ", reference " << num(c.reference)
            << "</title></circle>\n";
    }
    s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"" << line.str() << "\"/>\n"
      << marks.str();
    const double ly = kTop + 8 + 18 * double(j), lx = kWidth - kRight + 14;
    s << "<line x1=\"" << lx << "\" y1=\"" << ly << "\" x2=\"" << lx + 18 << "\" y2=\"" << ly << "\" stroke=\""
      << colour << "\" stroke-width=\"2\"/><text x=\"" << lx + 24 << "\" y=\"" << ly + 4
      << "\" font-size=\"11\">roughness " << num(grid.perceptualRoughness[j]) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace mb::report
