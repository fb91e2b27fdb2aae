#include "bench_engine/svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "bench_engine/cost_format.hpp"
#include "bench_engine/report.hpp"

namespace mb::bench {
namespace {

constexpr double kWidth = 820, kHeight = 540;
constexpr double kLeft = 90, kRight = 200, kTop = 64, kBottom = 72;  // margins
constexpr double kErrorFloor = 1e-12;  // an exact 0 is drawn here (log axis), labelled "= 0"

// Where an item is drawn: a resolved cost at its median, one below resolution at the bound
// it is below (with a bar from 0); never at a zero or negative cost.
double drawnCost(const CostMeasurement& c) { return c.resolved ? c.nsPerEval : c.nsUpperBound(); }
double barLow(const CostMeasurement& c) { return c.resolved ? c.nsPerEvalLow : 0.0; }
double barHigh(const CostMeasurement& c) { return c.resolved ? c.nsPerEvalHigh : c.nsUpperBound(); }

struct Axes {
  double x0, x1;            // cost range, ns
  int y0, y1;               // log10 error range (decades)
  double unitNs = 1;        // the tick labels' unit, in ns
  const char* unit = "ns";  // and its name
  double px(double cost) const { return kLeft + (cost - x0) / (x1 - x0) * (kWidth - kLeft - kRight); }
  double py(double err) const {
    double e = std::log10(std::max(err, kErrorFloor));
    return kHeight - kBottom - (e - y0) / double(y1 - y0) * (kHeight - kTop - kBottom);
  }
};

Axes axesFor(const BenchGroup& g) {
  double cmin = 0, cmax = 0, emin = INFINITY, emax = 0;
  for (const auto& it : g.items) {
    if (std::isfinite(barHigh(it.cost))) cmax = std::max(cmax, barHigh(it.cost));
    double e = it.error.maxScaled();
    if (std::isfinite(e)) {
      emin = std::min(emin, std::max(e, kErrorFloor));
      emax = std::max(emax, std::max(e, kErrorFloor));
    }
  }
  if (!std::isfinite(emin)) emin = emax = 1.0;
  Axes a{cmin, cmax > cmin ? cmax : cmin + 1.0, int(std::floor(std::log10(emin))), int(std::ceil(std::log10(emax)))};
  a.x1 += 0.08 * (a.x1 - a.x0);
  for (auto [scale, name] : {std::pair{1e-6, "fs"}, {1e-3, "ps"}, {1.0, "ns"}, {1e3, "µs"}, {1e6, "ms"}})
    if (a.x1 >= scale) a.unitNs = scale, a.unit = name;
  // Keep points off the frame: a value within a tenth of a decade of an edge gets one more.
  if (std::log10(emax) > a.y1 - 0.1) ++a.y1;
  if (std::log10(emin) < a.y0 + 0.1) --a.y0;
  return a;
}

void drawAxes(std::ostringstream& s, const Axes& a) {
  const double left = kLeft, right = kWidth - kRight, top = kTop, bottom = kHeight - kBottom;
  s << "<g font-size=\"12\" stroke-width=\"1\">\n";
  double step = niceStep((a.x1 - a.x0) / a.unitNs);
  for (double x = std::ceil(a.x0 / a.unitNs / step) * step; x <= a.x1 / a.unitNs + 1e-9 * step; x += step) {
    double X = a.px(x * a.unitNs);
    s << "<line x1=\"" << X << "\" y1=\"" << top << "\" x2=\"" << X << "\" y2=\"" << bottom
      << "\" stroke=\"#e6e6e6\"/>\n<text x=\"" << X << "\" y=\"" << bottom + 18 << "\" text-anchor=\"middle\">"
      << printfDouble("%g", std::abs(x) < 1e-9 * step ? 0.0 : x) << "</text>\n";
  }
  for (int d = a.y0; d <= a.y1; ++d) {
    double Y = a.py(std::pow(10.0, d));
    s << "<line x1=\"" << left << "\" y1=\"" << Y << "\" x2=\"" << right << "\" y2=\"" << Y
      << "\" stroke=\"#e6e6e6\"/>\n<text x=\"" << left - 8 << "\" y=\"" << Y + 4 << "\" text-anchor=\"end\">1e" << d
      << "</text>\n";
  }
  s << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\"" << bottom - top
    << "\" fill=\"none\" stroke=\"#333333\"/>\n";
  s << "<text x=\"" << (left + right) / 2 << "\" y=\"" << kHeight - 24
    << "\" text-anchor=\"middle\">cost per evaluation, " << a.unit
    << ", net of the empty loop (bars: 95 % interval; dashed: below resolution)</text>\n";
  s << "<text transform=\"translate(22 " << (top + bottom) / 2
    << ") rotate(-90)\" text-anchor=\"middle\">max error |x - truth| / max(1, |truth|) (log)</text>\n";
  s << "</g>\n";
}

struct Box {
  double x0, y0, x1, y1;
};

struct Placement {
  double x = 0, dy = 0;
  bool left = false;  // text-anchor end, to the left of the point
  Box box{};
};

// First free spot for a label of `chars` characters next to (X, Y): right of the point, then
// left, each at growing vertical offsets. 11 px sans-serif is ~6.2 px per character.
Placement placeLabel(double X, double Y, size_t chars, const std::vector<Box>& taken) {
  const double w = 6.2 * double(chars);
  Placement first;
  bool haveFirst = false;
  for (bool left : {false, true})
    for (double dy : {-7.0, 14.0, -20.0, 27.0, -33.0, 40.0, -46.0, 53.0}) {
      Placement p;
      p.left = left;
      p.dy = dy;
      p.x = left ? X - 8 : X + 8;
      p.box = {left ? p.x - w : p.x, Y + dy - 10, left ? p.x : p.x + w, Y + dy + 3};
      if (!haveFirst) first = p, haveFirst = true;
      bool inside =
          p.box.x0 >= 2 && p.box.x1 <= kWidth - 2 && p.box.y0 >= kTop - 12 && p.box.y1 <= kHeight - kBottom + 12;
      bool free = inside && std::none_of(taken.begin(), taken.end(), [&](const Box& b) {
                    return p.box.x0 < b.x1 && b.x0 < p.box.x1 && p.box.y0 < b.y1 && b.y0 < p.box.y1;
                  });
      if (free) return p;
    }
  return first;
}

}  // namespace

double niceStep(double range) {
  double p = std::pow(10.0, std::floor(std::log10(range / 5.0)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (range / (m * p) <= 6.0) return m * p;
  return 10.0 * p;
}

std::string xmlEscape(const std::string& in) {
  std::string out;
  for (char c : in) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string paretoSvg(const BenchGroup& g, const std::string& subtitle) {
  Axes a = axesFor(g);
  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
    << "\" viewBox=\"0 0 " << kWidth << " " << kHeight << "\" font-family=\"sans-serif\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << kLeft << "\" y=\"26\" font-size=\"16\" font-weight=\"bold\">" << xmlEscape(g.name)
    << ": run time against error</text>\n"
    << "<text x=\"" << kLeft << "\" y=\"46\" font-size=\"11\" fill=\"#555555\">" << xmlEscape(subtitle) << "</text>\n";
  drawAxes(s, a);

  // The frontier line, in cost order.
  std::vector<const BenchItem*> order;
  for (const auto& it : g.items) order.push_back(&it);
  std::stable_sort(order.begin(), order.end(),
                   [](auto* p, auto* q) { return drawnCost(p->cost) < drawnCost(q->cost); });
  s << "<polyline fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\" points=\"";
  for (const BenchItem* it : order)
    if (it->onFrontier) s << a.px(drawnCost(it->cost)) << "," << a.py(it->error.maxScaled()) << " ";
  s << "\"/>\n";

  // Points first, then labels placed greedily (in cost order) at the first spot that
  // overlaps no point and no earlier label, with a leader line when moved away.
  bool anyTruth = std::any_of(order.begin(), order.end(), [](auto* it) { return it->yardstick == "ground_truth"; });
  bool anyOffFrontierByYardstick =
      anyTruth && std::any_of(order.begin(), order.end(), [](auto* it) { return it->yardstick != "ground_truth"; });
  const double lx = kWidth - kRight + 14, ly = kTop + 10;
  std::vector<Box> taken{{lx - 6, ly - 8, kWidth, ly + (anyOffFrontierByYardstick ? 102 : 68)}};  // the legend
  std::vector<std::pair<double, double>> at;
  s << "<g>\n";
  for (const BenchItem* it : order) {
    double e = it->error.maxScaled();
    double X = a.px(drawnCost(it->cost)), Y = std::isfinite(e) ? a.py(e) : kTop + 6;
    at.push_back({X, Y});
    taken.push_back({X - 5, Y - 5, X + 5, Y + 5});
    s << "<line x1=\"" << a.px(barLow(it->cost)) << "\" y1=\"" << Y << "\" x2=\"" << a.px(barHigh(it->cost))
      << "\" y2=\"" << Y << "\" stroke=\"#888888\" stroke-width=\"1.2\""
      << (it->cost.resolved ? "" : " stroke-dasharray=\"3 2\"") << "/>\n";
    std::string tip = "<title>" + xmlEscape(it->id) + ": " + xmlEscape(formatCostWithInterval(it->cost)) + ", static " +
                      printfDouble("%.1f", it->staticCost) + " FMA, max error " + printfDouble("%.3g", e) +
                      (it->tiedWith.empty() ? "" : ", tie with " + xmlEscape(it->tiedWith)) + "</title>";
    if (anyTruth && it->yardstick != "ground_truth") {
      s << "<rect x=\"" << X - 4 << "\" y=\"" << Y - 4
        << "\" width=\"8\" height=\"8\" fill=\"#bbbbbb\" stroke=\"#777777\">" << tip << "</rect>\n";
    } else {
      s << "<circle cx=\"" << X << "\" cy=\"" << Y << "\" r=\"4.5\" stroke-width=\"1.5\" "
        << (it->onFrontier         ? "fill=\"#d62728\" stroke=\"#d62728\""
            : it->tiedWith.empty() ? "fill=\"white\" stroke=\"#555555\""
                                   : "fill=\"#f4b6b6\" stroke=\"#d62728\"")
        << ">" << tip << "</circle>\n";
    }
  }
  s << "</g>\n<g font-size=\"11\">\n";
  for (size_t k = 0; k < order.size(); ++k) {
    const BenchItem& it = *order[k];
    double e = it.error.maxScaled();
    std::string label = it.id + (it.yardstick == "reference" ? " (vs own ref.)" : "") +
                        (std::isfinite(e) ? (e == 0 ? " (= 0)" : "") : " (non-finite)") +
                        (it.cost.resolved ? "" : " (below resolution)");
    auto [X, Y] = at[k];
    Placement p = placeLabel(X, Y, label.size(), taken);
    taken.push_back(p.box);
    if (std::abs(p.dy) > 14)
      s << "<line x1=\"" << X << "\" y1=\"" << Y << "\" x2=\"" << p.x << "\" y2=\"" << Y + p.dy - 4
        << "\" stroke=\"#aaaaaa\" stroke-width=\"0.8\"/>\n";
    s << "<text x=\"" << p.x << "\" y=\"" << Y + p.dy << "\"" << (p.left ? " text-anchor=\"end\"" : "") << ">"
      << xmlEscape(label) << "</text>\n";
  }
  s << "</g>\n";
  // Legend.
  s << "<g font-size=\"11\"><circle cx=\"" << lx << "\" cy=\"" << ly << "\" r=\"4.5\" fill=\"#d62728\"/>"
    << "<text x=\"" << lx + 10 << "\" y=\"" << ly + 4 << "\">Pareto frontier</text>"
    << "<circle cx=\"" << lx << "\" cy=\"" << ly + 20
    << "\" r=\"4.5\" fill=\"white\" stroke=\"#555555\" stroke-width=\"1.5\"/>"
    << "<text x=\"" << lx + 10 << "\" y=\"" << ly + 24 << "\">dominated</text>"
    << "<circle cx=\"" << lx << "\" cy=\"" << ly + 40
    << "\" r=\"4.5\" fill=\"#f4b6b6\" stroke=\"#d62728\" stroke-width=\"1.5\"/>"
    << "<text x=\"" << lx + 10 << "\" y=\"" << ly + 44 << "\">tie: cheaper only within</text>"
    << "<text x=\"" << lx + 10 << "\" y=\"" << ly + 58 << "\">the noise of a better point</text>";
  if (anyOffFrontierByYardstick)
    s << "<rect x=\"" << lx - 4 << "\" y=\"" << ly + 76
      << "\" width=\"8\" height=\"8\" fill=\"#bbbbbb\" stroke=\"#777777\"/>"
      << "<text x=\"" << lx + 10 << "\" y=\"" << ly + 84 << "\">no ground truth: fp32</text>"
      << "<text x=\"" << lx + 10 << "\" y=\"" << ly + 98 << "\">error only, off frontier</text>";
  s << "</g>\n";
  s << "</svg>\n";
  return s.str();
}

}  // namespace mb::bench
