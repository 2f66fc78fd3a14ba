#include "model/io/apt_io.h"

#include <glog/logging.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "model/io/atomic_file.h"
#include "model/geometry/circular_arc.h"
#include "model/geometry/rational_curve.h"
#include "model/base/units.h"

namespace tpopt {
namespace {

constexpr double kMaxMagnitude = 1e6;

// s[begin, end) without the white space at its ends.
std::string Trim(const std::string& s, size_t begin = 0, size_t end = std::string::npos) {
  end = std::min(end, s.size());
  const size_t b = s.find_first_not_of(" \t\r\n", begin);
  if (b == std::string::npos || b >= end) return "";
  const size_t e = s.find_last_not_of(" \t\r\n", end - 1);
  return s.substr(b, e - b + 1);
}

// Trim without a copy: a new string per line costs a third of the reading
// time.
void TrimInPlace(std::string* s) {
  const size_t last = s->find_last_not_of(" \t\r\n");
  if (last == std::string::npos) {
    s->clear();
    return;
  }
  s->erase(last + 1);
  s->erase(0, s->find_first_not_of(" \t\r\n"));
}

// A plain decimal number as CAM systems write it (sign, digits, point,
// exponent). strtod alone would also take "0x1A", "nan" and "inf", none of
// which is a coordinate.
bool ParseDecimal(const std::string& text, double* out) {
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos) {
    return false;
  }
  char* end = nullptr;
  *out = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}

std::string Upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// One logical statement: major word, comma-separated arguments, first line.
struct Statement {
  std::string word;
  std::vector<std::string> args;
  int line = 0;
};

// The major word of the text before '/': "TOOL PATH" is the one two-word
// major word; otherwise the first token, so that "PARTNO BLADE 1" and
// "INSERT G05.1 Q1" read as PARTNO and INSERT (and warn once per word).
std::string MajorWord(const std::string& head) {
  // Hand-split: a string stream per statement halves the reading speed.
  const std::string upper = Upper(head);
  std::string tokens[2];
  size_t at = 0;
  for (std::string& token : tokens) {
    const size_t b = upper.find_first_not_of(" \t", at);
    if (b == std::string::npos) break;
    const size_t e = std::min(upper.find_first_of(" \t", b), upper.size());
    token = upper.substr(b, e - b);
    at = e;
  }
  if (tokens[0] == "TOOL" && tokens[1] == "PATH") return "TOOL PATH";
  return tokens[0];
}

Statement Split(const std::string& text, int line) {
  Statement st;
  st.line = line;
  const size_t slash = text.find('/');
  st.word = MajorWord(text.substr(0, slash));
  if (slash == std::string::npos) return st;
  // As std::getline(..., ',') splits: no empty argument after a final comma.
  for (size_t b = slash + 1; b < text.size();) {
    const size_t e = std::min(text.find(',', b), text.size());
    st.args.push_back(Trim(text, b, e));
    b = e + 1;
  }
  return st;
}

// Chords of a CIRCLE/ or NX NURBS/ curve stay this close to it (mm): far
// below a finishing tolerance, so the curve's points stand for the curve in
// every metric.
constexpr double kCurveChordMm = 0.001;
// How far a CIRCLE's end points or a NURBS's first control point may lie
// from where the record says (mm): CAM systems round to 4-6 decimals.
constexpr double kCurveFitMm = 0.01;

// tpopt's own span record (AptCurveSpan): degree 3, 4 points, clamped
// knots, then 4 x (x, y, z, 1).
bool IsTpoptSpan(const Statement& st) {
  static const char* kHead[] = {"3", "4", "0", "0", "0", "0", "1", "1", "1", "1"};
  if (st.args.size() != 26) return false;
  for (size_t k = 0; k < 10; ++k) {
    double v = 0.0, want = std::atof(kHead[k]);
    if (!ParseDecimal(st.args[k], &v) || v != want) return false;
  }
  return true;
}

class AptReader {
 public:
  AptReader(const std::string& name, ToolPath* path, std::vector<std::string>* warnings)
      : name_(name), path_(path), warnings_(warnings) {
    program_.format = ProgramFormat::kApt;
    program_.file = name;
  }

  Status Read(std::istream& in) {
    std::string line, raw, text;
    int first_line = 0, n = 0;
    while (std::getline(in, line)) {
      ++n;
      program_.final_newline = !in.eof();
      std::string code = line;
      const size_t comment = code.find("$$");
      if (comment != std::string::npos) code.erase(comment);
      TrimInPlace(&code);
      if (!raw.empty()) raw += '\n';
      raw += line;
      // Blank and comment-only lines separate statements, and some posts
      // put them between the lines of a continued one: they are kept as
      // written either way, and carry no statement.
      if (code.empty()) {
        if (text.empty()) {
          AddBlock(n, raw);
          raw.clear();
        }
        continue;
      }
      if (text.empty()) first_line = n;
      const bool continued = code.back() == '$';
      if (continued) code.pop_back();
      text += code;
      if (continued) continue;
      RETURN_IF_ERROR(Handle(Split(text, first_line), raw));
      text.clear();
      raw.clear();
    }
    if (!text.empty()) {
      return Error(first_line, "statement continued with '$' but the file ends");
    }
    RETURN_IF_ERROR(FinishCurve());
    if (path_->poses.empty()) return Status::Error(name_ + ": no GOTO: the path is empty");
    // Inch values within range may not be, in mm (the unit tpopt writes);
    // nor the points of an arc or curve.
    for (const ToolPose& p : path_->poses) {
      if (!(p.p_w_tip.cwiseAbs().maxCoeff() <= kMaxMagnitude)) {
        std::ostringstream err;
        err << "a move to (" << p.p_w_tip.transpose() << ") mm is out of range (|v| <= 1e6 mm)";
        return Error(p.source_line, err.str());
      }
      if (!(p.feed_mm_per_min <= kMaxMagnitude)) {
        return Error(p.source_line, "the feed " + std::to_string(p.feed_mm_per_min) +
                                        " mm/min is out of range (<= 1e6 mm/min)");
      }
    }
    for (const ToolRecord& t : path_->tools) {
      if (t.cutter && !(2 * t.cutter->radius_mm <= kMaxMagnitude &&
                        t.cutter->flute_length_mm <= kMaxMagnitude)) {
        return Error(t.source_line, "the tool's diameter " +
                                        std::to_string(2 * t.cutter->radius_mm) + " mm or length " +
                                        std::to_string(t.cutter->flute_length_mm) +
                                        " mm is out of range (<= 1e6 mm)");
      }
    }
    if (!path_->tools.empty()) {
      // The cutter a caller takes for the whole path: the one of the first
      // feed move (a program may load its tool before a rapid).
      int first = path_->poses.front().tool;
      for (const ToolPose& p : path_->poses) {
        if (!p.rapid && p.tool >= 0) {
          first = p.tool;
          break;
        }
      }
      if (first >= 0 && path_->tools[first].cutter) path_->cutter = path_->tools[first].cutter;
    }
    path_->program = std::make_shared<const Program>(std::move(program_));
    return Status::Ok();
  }

 private:
  Status Error(int line, const std::string& what) const {
    return Status::Error(name_ + ":" + std::to_string(line) + ": " + what);
  }

  std::string Where(int line) const { return name_ + ":" + std::to_string(line); }

  void AddBlock(int line, const std::string& raw) {
    ProgramBlock block;
    block.line = line;
    block.text = raw;
    block.mm_per_unit = mm_per_unit_;
    block.modal_feed = feed_ / mm_per_unit_;
    program_.blocks.push_back(std::move(block));
  }

  Status Number(const Statement& st, size_t k, double* out) const {
    const std::string& a = st.args[k];
    if (!ParseDecimal(a, out)) {
      return Error(st.line,
                   st.word + " argument " + std::to_string(k + 1) + " '" + a + "' is not a number");
    }
    if (!std::isfinite(*out) || std::abs(*out) > kMaxMagnitude) {
      return Error(st.line, st.word + " argument " + std::to_string(k + 1) + " '" + a +
                                "' is out of range (|v| <= 1e6)");
    }
    return Status::Ok();
  }

  // All arguments as numbers.
  Status Numbers(const Statement& st, std::vector<double>* out) const {
    out->resize(st.args.size());
    for (size_t k = 0; k < st.args.size(); ++k) {
      RETURN_IF_ERROR(Number(st, k, &(*out)[k]));
    }
    return Status::Ok();
  }

  // The last pose, and its block, stay where the program put them: a
  // record that follows them (a CIRCLE, a curve, a non-motion record)
  // expects the tool there.
  void HoldLastPose() {
    if (path_->poses.empty()) return;
    ToolPose& last = path_->poses.back();
    last.held = true;
    if (last.source_block >= 0) program_.blocks[last.source_block].replaceable = false;
  }

  ToolPose NewPose(const Eigen::Vector3d& p_w_tip, int line) const {
    ToolPose pose;
    pose.p_w_tip = p_w_tip;
    pose.a_w = axis_;
    pose.feed_mm_per_min = feed_;
    pose.source_line = line;
    pose.tool = tool_;
    return pose;
  }

  // Poses along a curve the program's records describe, up to (not
  // including) its end: held, and named by no block (the records are
  // written back as they were). The axis turns linearly from the last
  // pose's to `end_axis`.
  void AddCurvePoints(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& end_axis,
                      int line) {
    const Eigen::Vector3d start_axis = path_->poses.back().a_w;
    for (size_t k = 0; k + 1 < points.size(); ++k) {
      const double t = static_cast<double>(k + 1) / points.size();
      ToolPose pose = NewPose(points[k], line);
      pose.a_w = ((1 - t) * start_axis + t * end_axis).normalized();
      pose.held = true;
      path_->poses.push_back(pose);
    }
  }

  Status Goto(const Statement& st) {
    if (st.args.size() != 3 && st.args.size() != 6) {
      return Error(st.line, "GOTO needs 3 or 6 numbers, got " + std::to_string(st.args.size()));
    }
    std::vector<double> v;
    RETURN_IF_ERROR(Numbers(st, &v));
    if (st.args.size() == 6) {
      const Eigen::Vector3d a(v[3], v[4], v[5]);
      if (!(a.norm() > 1e-9)) {
        return Error(st.line, "zero-length tool axis (" + st.args[3] + ", " + st.args[4] + ", " +
                                  st.args[5] + ")");
      }
      axis_ = a.normalized();
    }
    const Eigen::Vector3d tip = mm_per_unit_ * Eigen::Vector3d(v[0], v[1], v[2]);
    ProgramBlock& block = program_.blocks.back();
    if (circle_) {
      if (path_->poses.empty()) return Error(circle_line_, "CIRCLE has no start point (GOTO)");
      std::vector<Eigen::Vector3d> points;
      RETURN_IF_ERROR(ArcPoints(
          *circle_, path_->poses.back().p_w_tip, tip, kCurveChordMm, kCurveFitMm,
          Where(circle_line_) + " (CIRCLE ending at line " + std::to_string(st.line) + ")",
          &points));
      AddCurvePoints(points, axis_, circle_line_);
    }
    ToolPose pose = NewPose(tip, st.line);
    pose.rapid = rapid_next_ || in_cycle_;
    // Kept as written: a rapid, a cycle position, an arc's end, a point of
    // a span tpopt wrote, and the first move after a record that breaks
    // the run.
    pose.held = pose.rapid || circle_.has_value() || in_span_ || hold_next_;
    pose.source_block = static_cast<int>(program_.blocks.size()) - 1;
    block.pose = static_cast<int>(path_->poses.size());
    block.replaceable = !pose.held;
    rapid_next_ = false;
    hold_next_ = false;
    circle_.reset();
    path_->poses.push_back(pose);
    return Status::Ok();
  }

  // CIRCLE/xc,yc,zc,i,j,k,r[,...]: the next GOTO goes there along the arc,
  // counter-clockwise about (i, j, k); NX adds tolerance and tool data.
  Status Circle(const Statement& st) {
    if (st.args.size() < 7) {
      return Error(st.line, "CIRCLE needs centre, axis and radius (7 numbers), got " +
                                std::to_string(st.args.size()));
    }
    double v[7];
    for (size_t k = 0; k < 7; ++k) {
      RETURN_IF_ERROR(Number(st, k, &v[k]));
    }
    CircularArc arc;
    arc.center = mm_per_unit_ * Eigen::Vector3d(v[0], v[1], v[2]);
    arc.axis = Eigen::Vector3d(v[3], v[4], v[5]);
    arc.radius_mm = mm_per_unit_ * v[6];
    if (!(arc.axis.norm() > 1e-9) || !(arc.radius_mm > 0)) {
      return Error(st.line, "CIRCLE axis (" + st.args[3] + ", " + st.args[4] + ", " + st.args[5] +
                                ") or radius " + st.args[6] + " is zero");
    }
    if (path_->poses.empty()) return Error(st.line, "CIRCLE has no start point (GOTO)");
    HoldLastPose();
    circle_ = arc;
    circle_line_ = st.line;
    return Status::Ok();
  }

  // NX spline motion: NURBS/, then KNOT/ records (their numbers, in order,
  // make the knot vector) and CNTRL/x,y,z[,w] records, one a control point.
  Status CurveRecord(const Statement& st) {
    std::vector<double> v;
    RETURN_IF_ERROR(Numbers(st, &v));
    if (st.word == "KNOT") {
      for (double k : v) curve_->knots.push_back(mm_per_unit_ * k);
      return Status::Ok();
    }
    if (v.size() != 3 && v.size() != 4) {
      return Error(st.line,
                   "CNTRL needs x,y,z[,w] (3 or 4 numbers), got " + std::to_string(v.size()));
    }
    curve_->control_points.push_back(mm_per_unit_ * Eigen::Vector3d(v[0], v[1], v[2]));
    curve_->weights.push_back(v.size() == 4 ? v[3] : 1.0);
    curve_end_block_ = static_cast<int>(program_.blocks.size()) - 1;
    return Status::Ok();
  }

  Status FinishCurve() {
    if (!curve_) return Status::Ok();
    RationalCurve curve = std::move(*curve_);
    curve_.reset();
    const std::string what = Where(curve_line_) + " (NURBS)";
    const int n = static_cast<int>(curve.control_points.size());
    curve.degree = static_cast<int>(curve.knots.size()) - n - 1;
    if (n < 2 || curve.degree < 1) {
      return Status::Error(what + ": " + std::to_string(curve.knots.size()) + " knots and " +
                           std::to_string(n) + " control points (CNTRL) make no curve");
    }
    std::vector<Eigen::Vector3d> points;
    RETURN_IF_ERROR(RationalCurvePoints(curve, kCurveChordMm, what, &points));
    const Eigen::Vector3d start = RationalCurvePoint(curve, 0.0);
    if ((start - path_->poses.back().p_w_tip).norm() > kCurveFitMm) {
      std::ostringstream err;
      err << what << ": the curve starts at (" << start.transpose() / mm_per_unit_
          << "), not where the tool is (" << path_->poses.back().p_w_tip.transpose() / mm_per_unit_
          << ")";
      return Status::Error(err.str());
    }
    AddCurvePoints(points, axis_, curve_line_);
    ToolPose end = NewPose(points.back(), program_.blocks[curve_end_block_].line);
    end.held = true;
    end.source_block = curve_end_block_;
    program_.blocks[curve_end_block_].pose = static_cast<int>(path_->poses.size());
    path_->poses.push_back(end);
    return Status::Ok();
  }

  Status Tool(const Statement& st, size_t first_number) {
    if (st.args.size() <= first_number) return Error(st.line, st.word + " has no diameter");
    ToolRecord tool;
    tpopt::Cutter cutter;
    double d = 0.0;
    RETURN_IF_ERROR(Number(st, first_number, &d));
    cutter.radius_mm = 0.5 * mm_per_unit_ * d;
    if (st.args.size() > first_number + 1) {
      RETURN_IF_ERROR(Number(st, first_number + 1, &tool.corner_radius_mm));
      tool.corner_radius_mm *= mm_per_unit_;
    }
    if (st.word == "TLDATA" && st.args.size() > first_number + 2) {
      RETURN_IF_ERROR(Number(st, first_number + 2, &cutter.flute_length_mm));
      cutter.flute_length_mm *= mm_per_unit_;
    }
    RETURN_IF_ERROR(cutter.Validate(Where(st.line)));
    if (!(tool.corner_radius_mm >= 0 && tool.corner_radius_mm <= cutter.radius_mm)) {
      return Error(st.line, st.word + " corner radius " + st.args[first_number + 1] +
                                " must be in [0, the cutter's radius]");
    }
    tool.cutter = cutter;
    tool.source_line = st.line;
    // NX writes TLDATA after LOAD/TOOL, APT CUTTER before LOADTL: a LOAD
    // and a geometry record with no move between them are one tool.
    if (load_waiting_) {
      tool.number = path_->tools[tool_].number;
      path_->tools[tool_] = tool;
      load_waiting_ = false;
    } else {
      path_->tools.push_back(tool);
      tool_ = static_cast<int>(path_->tools.size()) - 1;
      geometry_waiting_ = true;
    }
    return Status::Ok();
  }

  // LOAD/TOOL,n[,...] or LOADTL/n[,...].
  Status Load(const Statement& st, size_t number_arg) {
    double n = 0.0;
    if (st.args.size() <= number_arg || !ParseDecimal(st.args[number_arg], &n) ||
        n != std::floor(n) || n < 0 || n > 1e6) {
      return Error(st.line, st.word + " needs a tool number");
    }
    const int number = static_cast<int>(n);
    if (geometry_waiting_) {
      path_->tools[tool_].number = number;
      geometry_waiting_ = false;
      return Status::Ok();
    }
    ToolRecord tool;
    tool.number = number;
    tool.source_line = st.line;
    // The same tool loaded again has the geometry it had.
    for (const ToolRecord& t : path_->tools) {
      if (t.number == number && t.cutter) {
        tool.cutter = t.cutter;
        tool.corner_radius_mm = t.corner_radius_mm;
      }
    }
    path_->tools.push_back(tool);
    tool_ = static_cast<int>(path_->tools.size()) - 1;
    load_waiting_ = true;
    return Status::Ok();
  }

  // FEDRAT/[MMPM|IPM,]f or FEDRAT/f[,MMPM|IPM]: f in the program's length
  // unit per minute.
  Status Feed(const Statement& st) {
    std::string unit;
    size_t value = st.args.size();
    for (size_t k = 0; k < st.args.size(); ++k) {
      const std::string word = Upper(st.args[k]);
      if (word == "IPR" || word == "MMPR") {
        return Error(st.line, "FEDRAT unit " + word + " (per revolution) is not supported");
      }
      if (word == "MMPM" || word == "IPM") {
        unit = word;
      } else if (!word.empty() && value == st.args.size()) {
        value = k;
      }
    }
    if (value == st.args.size()) return Error(st.line, "FEDRAT has no feed value");
    if (unit == "IPM" && !units_known_) SwitchToInch();  // NX: IPM and no UNITS
    if (!unit.empty() && (unit == "IPM") != (mm_per_unit_ != 1.0)) {
      return Error(st.line, "FEDRAT/" + unit + " in a program whose units are " +
                                (mm_per_unit_ != 1.0 ? "inches" : "mm"));
    }
    double f = 0.0;
    RETURN_IF_ERROR(Number(st, value, &f));
    if (!(f > 0)) return Error(st.line, "FEDRAT " + st.args[value] + " must be > 0");
    feed_ = f * mm_per_unit_;
    program_.blocks.back().modal_feed = f;
    return Status::Ok();
  }

  // The program is in inch from its start: a program with no UNITS record
  // whose first FEDRAT says IPM (NX writes no UNITS/INCHES).
  void SwitchToInch() {
    units_known_ = true;
    if (mm_per_unit_ == kMmPerInch) return;
    mm_per_unit_ = kMmPerInch;
    for (ToolPose& p : path_->poses) {
      p.p_w_tip *= kMmPerInch;
      p.feed_mm_per_min *= kMmPerInch;
    }
    for (ToolRecord& t : path_->tools) {
      if (!t.cutter) continue;
      t.cutter->radius_mm *= kMmPerInch;
      t.cutter->flute_length_mm *= kMmPerInch;
      t.corner_radius_mm *= kMmPerInch;
    }
    feed_ *= kMmPerInch;
    for (ProgramBlock& b : program_.blocks) b.mm_per_unit = kMmPerInch;
  }

  Status Units(const Statement& st) {
    const std::string unit = st.args.empty() ? "" : Upper(st.args[0]);
    if (unit == "MM") {
      if (mm_per_unit_ != 1.0) return Error(st.line, "UNITS/MM after inch records");
      units_known_ = true;
      return Status::Ok();
    }
    if (unit == "INCHES" || unit == "INCH") {
      if (mm_per_unit_ == 1.0 && !path_->poses.empty()) {
        return Error(st.line, "UNITS/" + st.args[0] + " after the first GOTO (read in mm)");
      }
      SwitchToInch();
      return Status::Ok();
    }
    return Error(st.line, "UNITS/" + (st.args.empty() ? std::string() : st.args[0]) +
                              " is not supported (MM or INCHES)");
  }

  Status Handle(const Statement& st, const std::string& raw) {
    const bool curve_record = st.word == "KNOT" || st.word == "CNTRL";
    if (curve_ && !curve_record) {
      RETURN_IF_ERROR(FinishCurve());
      hold_next_ = true;
    }
    AddBlock(st.line, raw);
    if (circle_ && st.word != "GOTO") {
      return Error(circle_line_, "CIRCLE is not followed by the GOTO to its end point (line " +
                                     std::to_string(st.line) + " is " + st.word + ")");
    }
    if (st.word == "GOTO") {
      load_waiting_ = geometry_waiting_ = false;
      return Goto(st);
    }
    if (curve_record) {
      if (!curve_) return Error(st.line, st.word + " outside a NURBS curve");
      return CurveRecord(st);
    }
    // Every other record that can matter to the machine breaks the run:
    // the moves on both sides of it stay where the program put them. Those
    // that only label, set the feed (written again where a replaced move
    // needs it) or mark the end change nothing there, and a RAPID's target
    // is kept by itself (the cut into it may end elsewhere).
    static const std::set<std::string> kNoMotion = {"FEDRAT",      "PAINT", "MULTAX", "TOOL PATH",
                                                    "PARTNO",      "UNITS", "PPRINT", "MACHIN",
                                                    "END-OF-PATH", "FINI",  "END",    "RAPID"};
    if (kNoMotion.count(st.word) == 0 && !path_->poses.empty()) {
      HoldLastPose();
      hold_next_ = true;
      in_span_ = false;
    }
    if (st.word == "RAPID") in_span_ = false;
    if (st.word == "CIRCLE") return Circle(st);
    if (st.word == "NURBS") {
      if (IsTpoptSpan(st)) {
        in_span_ = true;  // its GOTOs are its points, kept as written
        return Status::Ok();
      }
      if (path_->poses.empty()) return Error(st.line, "NURBS has no start point (GOTO)");
      curve_ = RationalCurve();
      curve_line_ = st.line;
      return Status::Ok();
    }
    if (st.word == "TLDATA") return Tool(st, 1);  // TLDATA/MILL,d,r,l
    if (st.word == "CUTTER") return Tool(st, 0);
    if (st.word == "LOADTL") return Load(st, 0);
    if (st.word == "LOAD" && !st.args.empty() && Upper(st.args[0]) == "TOOL") return Load(st, 1);
    if (st.word == "FEDRAT") return Feed(st);
    if (st.word == "UNITS") return Units(st);
    if (st.word == "RAPID") {
      rapid_next_ = true;
      return Status::Ok();
    }
    if (st.word == "CYCLE") {
      in_cycle_ = !(st.args.size() == 1 && Upper(st.args[0]) == "OFF");
      return Status::Ok();
    }
    static const std::set<std::string> kKnown = {
        "MULTAX", "TOOL PATH", "PAINT",  "END-OF-PATH", "FINI",   "PARTNO", "SPINDL", "COOLNT",
        "CUTCOM", "INSERT",    "SELECT", "CSYS",        "MSYS",   "LOAD",   "STOP",   "OPSTOP",
        "END",    "PPRINT",    "ORIGIN", "DELAY",       "MACHIN", "AUTO",   "CLRSRF", ""};
    if (kKnown.count(st.word) == 0 && warned_.insert(st.word).second && warnings_) {
      warnings_->push_back(Where(st.line) + ": statement '" + st.word +
                           "' is not understood; passed through as written (warned once)");
    }
    return Status::Ok();
  }

  std::string name_;
  ToolPath* path_;
  std::vector<std::string>* warnings_;
  Program program_;
  Eigen::Vector3d axis_ = Eigen::Vector3d::UnitZ();
  double feed_ = 0.0;         // mm/min
  double mm_per_unit_ = 1.0;  // 25.4 in inch
  bool units_known_ = false;  // a UNITS record, or an IPM feed, was read
  bool rapid_next_ = false;
  bool hold_next_ = false;             // the next GOTO follows a run-breaking record
  bool in_cycle_ = false;              // between CYCLE/... and CYCLE/OFF
  bool in_span_ = false;               // after one of tpopt's own NURBS spans
  std::optional<CircularArc> circle_;  // a CIRCLE waiting for its GOTO
  int circle_line_ = 0;
  std::optional<RationalCurve> curve_;  // an NX NURBS being read
  int curve_line_ = 0;
  int curve_end_block_ = -1;
  int tool_ = -1;                  // index into ToolPath::tools of the current tool
  bool load_waiting_ = false;      // it came from a LOAD, its geometry may follow
  bool geometry_waiting_ = false;  // it came from TLDATA/CUTTER, its LOAD may follow
  std::set<std::string> warned_;
};

}  // namespace

Status ReadAptStream(std::istream& in, const std::string& name, ToolPath* tool_path,
                     std::vector<std::string>* warnings) {
  ToolPath path;
  AptReader reader(name, &path, warnings);
  RETURN_IF_ERROR(reader.Read(in));
  *tool_path = std::move(path);
  return Status::Ok();
}

Status ReadApt(const std::string& path, ToolPath* tool_path, std::vector<std::string>* warnings) {
  std::ifstream in(path);
  if (!in) return Status::Error(path + ": cannot open file");
  return ReadAptStream(in, path, tool_path, warnings);
}

namespace {

// The title on one comment line: a line break in it (a file name, a flag
// value) would otherwise start a statement of its own.
std::string CommentLine(const std::string& title) {
  std::string line = title.empty() ? std::string("tpopt tool path") : title;
  for (char& c : line) {
    if (std::iscntrl(static_cast<unsigned char>(c))) c = ' ';
  }
  return "$$ " + line + "\n";
}

// What the reader would refuse: a written file must read back.
Status CheckWritable(const std::string& path, const ToolPath& tool_path) {
  if (tool_path.poses.empty()) return Status::Error(path + ": no poses to write");
  for (size_t i = 0; i < tool_path.poses.size(); ++i) {
    const ToolPose& p = tool_path.poses[i];
    const bool in_range = p.p_w_tip.allFinite() && p.a_w.allFinite() &&
                          p.p_w_tip.cwiseAbs().maxCoeff() <= kMaxMagnitude;
    if (!in_range || !(p.a_w.norm() > 1e-9)) {
      std::ostringstream err;
      err << path << ": pose " << i << " cannot be written: tip (" << p.p_w_tip.transpose()
          << ") mm, axis (" << p.a_w.transpose() << ")";
      return Status::Error(err.str());
    }
  }
  return Status::Ok();
}

Status CheckSpans(const std::string& path, const ToolPath& tool_path,
                  const std::vector<AptCurveSpan>& spans) {
  for (size_t k = 0; k < spans.size(); ++k) {
    bool finite = true;
    for (const Eigen::Vector3d& p : spans[k].bezier) {
      finite = finite && p.allFinite() && p.cwiseAbs().maxCoeff() <= kMaxMagnitude;
    }
    const bool ordered = k == 0 || spans[k].after_pose > spans[k - 1].after_pose;
    if (!finite || !ordered || spans[k].after_pose >= tool_path.poses.size()) {
      return Status::Error(path + ": curve span " + std::to_string(k) + " after pose " +
                           std::to_string(spans[k].after_pose) +
                           " cannot be written (out of order, past the last "
                           "pose or not finite)");
    }
  }
  return Status::Ok();
}

std::string NurbsRecord(const AptCurveSpan& span) {
  std::string out = "NURBS/3,4,0,0,0,0,1,1,1,1";
  char buf[128];
  for (const Eigen::Vector3d& p : span.bezier) {
    std::snprintf(buf, sizeof(buf), ",$\n%.9f,%.9f,%.9f,1", p.x(), p.y(), p.z());
    out += buf;
  }
  return out + "\n";
}

}  // namespace

namespace {

// Text of a GOTO for a replaced move, in its block's units.
std::string GotoRecord(const ToolPose& p, double mm_per_unit) {
  char buf[256];
  const Eigen::Vector3d tip = p.p_w_tip / mm_per_unit;
  // 6 decimals of mm, 7 of inch: both below 3e-6 mm.
  std::snprintf(buf, sizeof(buf),
                mm_per_unit == 1.0 ? "GOTO/%.6f,%.6f,%.6f,%.9f,%.9f,%.9f\n"
                                   : "GOTO/%.7f,%.7f,%.7f,%.9f,%.9f,%.9f\n",
                tip.x(), tip.y(), tip.z(), p.a_w.x(), p.a_w.y(), p.a_w.z());
  return buf;
}

std::string FeedRecord(double feed_per_min, double mm_per_unit) {
  char buf[64];
  // Ten digits: a scheduled feed reads back as written, not rounded.
  std::snprintf(buf, sizeof(buf), "FEDRAT/%s,%.10g\n", mm_per_unit == 1.0 ? "MMPM" : "IPM",
                feed_per_min);
  return buf;
}

bool SameFeed(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

}  // namespace

Status FormatAptProgram(const ToolPath& input, const ToolPath& output,
                        const std::vector<AptCurveSpan>& spans, std::string* text) {
  CHECK(input.program != nullptr && input.program->format == ProgramFormat::kApt)
      << "FormatAptProgram needs the APT program the input was read from";
  const Program& program = *input.program;
  std::vector<ProgramItem> items;
  RETURN_IF_ERROR(SpliceProgram(program, input, output, &items));
  // Each item's units: those of the block it is or that its new poses
  // come before (the replaced move's).
  std::vector<double> unit(items.size(), 1.0);
  double next_unit = program.blocks.empty() ? 1.0 : program.blocks.back().mm_per_unit;
  for (size_t k = items.size(); k-- > 0;) {
    if (items[k].block >= 0) next_unit = program.blocks[items[k].block].mm_per_unit;
    unit[k] = next_unit;
  }
  std::string out;
  out.reserve(64 * (program.blocks.size() + output.poses.size()));
  double file_feed = 0.0;  // the feed in effect in what is written, units/min
  size_t next_pose = 0, next_span = 0;
  for (size_t k = 0; k < items.size(); ++k) {
    const ProgramItem& item = items[k];
    size_t pose = output.poses.size();  // the output pose this item writes, if any
    if (item.block >= 0) {
      const ProgramBlock& block = program.blocks[item.block];
      // A record written as it was may rely on the source's modal feed.
      const double source_feed = item.block > 0 ? program.blocks[item.block - 1].modal_feed : 0.0;
      if (source_feed > 0 && !SameFeed(file_feed, source_feed)) {
        out += FeedRecord(source_feed, block.mm_per_unit);
      }
      out += block.text;
      out += '\n';
      file_feed = block.modal_feed;
      if (block.pose >= 0) {
        while (next_pose < output.poses.size() &&
               output.poses[next_pose].source_block != item.block) {
          ++next_pose;
        }
        pose = next_pose++;
      }
    } else {
      pose = static_cast<size_t>(item.pose);
      next_pose = pose + 1;
      const ToolPose& p = output.poses[pose];
      const double feed = p.feed_mm_per_min / unit[k];
      if (feed > 0 && !SameFeed(file_feed, feed)) {
        out += FeedRecord(feed, unit[k]);
        file_feed = feed;
      }
      out += GotoRecord(p, unit[k]);
    }
    if (next_span < spans.size() && spans[next_span].after_pose == pose) {
      out += NurbsRecord(spans[next_span++]);
    }
  }
  if (!program.final_newline && !out.empty() && out.back() == '\n') out.pop_back();
  *text = std::move(out);
  return Status::Ok();
}

Status WriteAptProgram(const std::string& path, const ToolPath& input, const ToolPath& output,
                       const std::vector<AptCurveSpan>& spans) {
  Status s = CheckWritable(path, output);
  if (s.ok()) s = CheckSpans(path, output, spans);
  std::string text;
  if (s.ok()) s = FormatAptProgram(input, output, spans, &text);
  if (!s.ok()) return Status::Error(path + ": " + s.message());
  return WriteFileAtomically(path, text);
}

std::string FormatApt(const ToolPath& tool_path, const std::vector<AptCurveSpan>& spans) {
  std::string out;
  out.reserve(64 * tool_path.poses.size() + 256);
  char buf[256];
  out += CommentLine(tool_path.title);
  out += "TOOL PATH/TPOPT\nUNITS/MM\nMULTAX/ON\n";
  // A path that names its tools gets each, with its corner radius, where
  // its moves start; otherwise the one cutter, sharp-cornered.
  const bool per_tool = !tool_path.tools.empty();
  if (tool_path.cutter && !per_tool) {
    std::snprintf(buf, sizeof(buf), "TLDATA/MILL,%.6f,0.000000,%.6f\n",
                  2 * tool_path.cutter->radius_mm, tool_path.cutter->flute_length_mm);
    out += buf;
  }
  double feed = -1.0;
  size_t next_span = 0;
  int tool = -1;
  for (size_t i = 0; i < tool_path.poses.size(); ++i) {
    const ToolPose& p = tool_path.poses[i];
    if (per_tool && p.tool >= 0 && p.tool != tool &&
        static_cast<size_t>(p.tool) < tool_path.tools.size()) {
      tool = p.tool;
      const ToolRecord& t = tool_path.tools[tool];
      if (t.cutter) {
        std::snprintf(buf, sizeof(buf), "TLDATA/MILL,%.6f,%.6f,%.6f\n", 2 * t.cutter->radius_mm,
                      t.corner_radius_mm, t.cutter->flute_length_mm);
        out += buf;
      }
      std::snprintf(buf, sizeof(buf), "LOAD/TOOL,%d\n", t.number);
      out += buf;
    }
    if (p.rapid) {
      out += "RAPID\n";
    } else if (p.feed_mm_per_min > 0 && p.feed_mm_per_min != feed) {
      feed = p.feed_mm_per_min;
      // Ten digits: a scheduled feed reads back as written, not rounded.
      std::snprintf(buf, sizeof(buf), "FEDRAT/MMPM,%.10g\n", feed);
      out += buf;
    }
    std::snprintf(buf, sizeof(buf), "GOTO/%.6f,%.6f,%.6f,%.9f,%.9f,%.9f\n", p.p_w_tip.x(),
                  p.p_w_tip.y(), p.p_w_tip.z(), p.a_w.x(), p.a_w.y(), p.a_w.z());
    out += buf;
    if (next_span < spans.size() && spans[next_span].after_pose == i) {
      out += NurbsRecord(spans[next_span++]);
    }
  }
  out += "END-OF-PATH\nFINI\n";
  return out;
}

Status WriteApt(const std::string& path, const ToolPath& tool_path,
                const std::vector<AptCurveSpan>& spans) {
  RETURN_IF_ERROR(CheckWritable(path, tool_path));
  RETURN_IF_ERROR(CheckSpans(path, tool_path, spans));
  return WriteFileAtomically(path, FormatApt(tool_path, spans));
}

}  // namespace tpopt
