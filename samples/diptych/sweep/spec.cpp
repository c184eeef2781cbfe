#include "samples/diptych/sweep/spec.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "engine/core/error.h"
#include "samples/diptych/parse_size.h"

namespace diptych::cli {
namespace {

// "2" -> 2, "true" -> true, anything else stays a string (a mode name).
nlohmann::json parseValue(const std::string& s) {
  if (s == "true" || s == "false") return s == "true";
  try {
    std::size_t used = 0;
    const double d = std::stod(s, &used);
    if (used == s.size()) {
      if (std::floor(d) == d && std::abs(d) < 1e9 && s.find_first_of(".eE") == std::string::npos)
        return int(d);
      return d;
    }
  } catch (const std::exception&) {
  }
  return s;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = s.find(sep, start);
    out.push_back(s.substr(start, end - start));
    if (end == std::string::npos) return out;
    start = end + 1;
  }
}

}  // namespace

const char* axisOption(AxisKind kind) {
  switch (kind) {
    case AxisKind::Light:
      return "--vary-light";
    case AxisKind::View:
      return "--vary-view";
    case AxisKind::Pass:
      break;
  }
  return "--vary";
}

SweepAxis parseAxis(const std::string& text, AxisKind kind) {
  const std::string option = axisOption(kind);
  const bool light = kind == AxisKind::Light, view = kind == AxisKind::View;
  auto fail = [&](const std::string& message) {
    throw InputError(option, text,
                     message +
                         " (expected KEY=V1,V2,... or KEY=START:STOP:STEP or "
                         "KEY=START:STOP:logN)");
  };
  SweepAxis axis;
  axis.text = text;
  axis.kind = kind;
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) fail("missing KEY=");
  axis.key = text.substr(0, eq);
  const std::string rest = text.substr(eq + 1);
  if (light && std::find(lightKeys().begin(), lightKeys().end(), axis.key) == lightKeys().end())
    fail("unknown light key '" + axis.key + "' (known: elevation, azimuth)");
  if (view && std::find(viewKeys().begin(), viewKeys().end(), axis.key) == viewKeys().end())
    fail("unknown view key '" + axis.key + "' (known: size, camera_azimuth, camera_distance)");
  if (rest.empty()) fail("empty range");
  const auto range = split(rest, ':');
  if (range.size() == 3) {
    const nlohmann::json a = parseValue(range[0]), b = parseValue(range[1]);
    if (!a.is_number() || !b.is_number()) fail("range bounds must be numbers");
    const double start = a.get<double>(), stop = b.get<double>();
    if (range[2].rfind("log", 0) == 0) {  // logN: N points spaced evenly in log
      const nlohmann::json n = parseValue(range[2].substr(3));
      if (!n.is_number_integer() || n.get<int>() < 1 || n.get<int>() > 10000)
        fail("logN needs an integer N in 1..10000");
      if (!(start > 0) || !(stop >= start))
        fail("empty range: a log range needs 0 < START <= STOP");
      const int count = n.get<int>();
      for (int i = 0; i < count; ++i)
        axis.values.push_back(count == 1 ? start
                                         : start * std::pow(stop / start, double(i) / (count - 1)));
    } else {
      const nlohmann::json s = parseValue(range[2]);
      if (!s.is_number() || !(s.get<double>() > 0)) fail("STEP must be a number > 0");
      const double step = s.get<double>();
      if (!(stop >= start)) fail("empty range: STOP < START");
      const bool integral = a.is_number_integer() && b.is_number_integer() && s.is_number_integer();
      const double count = std::floor((stop - start) / step + 1e-9) + 1;
      if (count > 10000) fail("more than 10000 values");
      for (int i = 0; i < int(count); ++i) {
        const double v = start + i * step;
        axis.values.push_back(integral ? nlohmann::json(int(std::lround(v))) : nlohmann::json(v));
      }
    }
  } else if (range.size() == 1) {
    std::set<std::string> seen;
    for (const std::string& item : split(rest, ',')) {
      if (item.empty()) fail("empty value in the list");
      if (!seen.insert(item).second) fail("value '" + item + "' listed twice");
      axis.values.push_back(parseValue(item));
    }
  } else {
    fail("a range has exactly three parts");
  }
  if (light)
    for (const auto& v : axis.values)
      if (!v.is_number()) fail("light angles are numbers (degrees)");
  if (view)
    for (const auto& v : axis.values) {
      if (axis.key == "size") {
        if (!v.is_string()) fail("sizes are WIDTHxHEIGHT");
        try {
          parseSize(v.get<std::string>(), kMaxSweepSide);
        } catch (const InputError& e) {
          fail(e.message());
        }
      } else if (!v.is_number()) {
        fail("camera values are numbers");
      } else if (axis.key == "camera_distance" && !(v.get<double>() > 0)) {
        fail("camera_distance is a factor > 0");
      }
    }
  return axis;
}

std::vector<nlohmann::json> cartesianProduct(const std::vector<SweepAxis>& input) {
  std::vector<SweepAxis> axes = input;
  std::stable_partition(axes.begin(), axes.end(),
                        [](const SweepAxis& a) { return a.kind != AxisKind::Pass; });
  std::set<std::string> keys;
  for (const SweepAxis& a : axes)
    if (!keys.insert(a.key).second)
      throw InputError(axisOption(a.kind), a.text, "key '" + a.key + "' is swept twice");
  // Each axis is bounded; their product must be too (every point is checked before rendering).
  double count = 1;
  for (const SweepAxis& a : axes) count *= double(a.values.size());
  if (count > double(kMaxSweepPoints))
    throw InputError("--vary", "",
                     fmt::format("the sweep has {:.0f} points (limit {}): sweep fewer values",
                                 count, kMaxSweepPoints));
  std::vector<nlohmann::json> points = {nlohmann::json::object()};
  for (const SweepAxis& a : axes) {
    std::vector<nlohmann::json> next;
    for (const auto& p : points)
      for (const auto& v : a.values) {
        nlohmann::json q = p;
        q[a.key] = v;
        next.push_back(std::move(q));
      }
    points = std::move(next);
  }
  return points;
}

}  // namespace diptych::cli
