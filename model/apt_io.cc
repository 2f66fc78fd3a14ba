#include "model/apt_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "model/atomic_file.h"

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
  if (text.empty() ||
      text.find_first_not_of("0123456789+-.eE") != std::string::npos) {
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

class AptReader {
 public:
  AptReader(const std::string& name, ToolPath* path, std::vector<std::string>* warnings)
      : name_(name), path_(path), warnings_(warnings) {}

  Status Read(std::istream& in) {
    std::string line, text;
    int first_line = 0;
    for (int n = 1; std::getline(in, line); ++n) {
      const size_t comment = line.find("$$");
      if (comment != std::string::npos) line.erase(comment);
      TrimInPlace(&line);
      // Blank and comment-only lines separate statements, and some posts
      // put them between the lines of a continued one: skip them either way.
      if (line.empty()) continue;
      if (text.empty()) first_line = n;
      const bool continued = line.back() == '$';
      if (continued) line.pop_back();
      text += line;
      if (continued) continue;
      Status s = Handle(Split(text, first_line));
      if (!s.ok()) return s;
      text.clear();
    }
    if (!text.empty()) {
      return Error(first_line, "statement continued with '$' but the file ends");
    }
    if (path_->poses.empty()) return Status::Error(name_ + ": no GOTO: the path is empty");
    return Status::Ok();
  }

 private:
  Status Error(int line, const std::string& what) const {
    return Status::Error(name_ + ":" + std::to_string(line) + ": " + what);
  }

  Status Number(const Statement& st, size_t k, double* out) const {
    const std::string& a = st.args[k];
    if (!ParseDecimal(a, out)) {
      return Error(st.line, st.word + " argument " + std::to_string(k + 1) + " '" + a +
                                "' is not a number");
    }
    if (!std::isfinite(*out) || std::abs(*out) > kMaxMagnitude) {
      return Error(st.line, st.word + " argument " + std::to_string(k + 1) + " '" + a +
                                "' is out of range (|v| <= 1e6)");
    }
    return Status::Ok();
  }

  Status Goto(const Statement& st) {
    if (st.args.size() != 3 && st.args.size() != 6) {
      return Error(st.line, "GOTO needs 3 or 6 numbers, got " + std::to_string(st.args.size()));
    }
    double v[6];
    for (size_t k = 0; k < st.args.size(); ++k) {
      Status s = Number(st, k, &v[k]);
      if (!s.ok()) return s;
    }
    if (st.args.size() == 6) {
      const Eigen::Vector3d a(v[3], v[4], v[5]);
      if (!(a.norm() > 1e-9)) {
        return Error(st.line, "zero-length tool axis (" + st.args[3] + ", " + st.args[4] + ", " +
                                  st.args[5] + ")");
      }
      axis_ = a.normalized();
    }
    ToolPose pose;
    pose.p_w_tip = Eigen::Vector3d(v[0], v[1], v[2]);
    pose.a_w = axis_;
    pose.feed_mm_per_min = feed_;
    pose.rapid = rapid_next_;
    pose.source_line = st.line;
    rapid_next_ = false;
    path_->poses.push_back(pose);
    return Status::Ok();
  }

  Status Cutter(const Statement& st, size_t first_number) {
    if (st.args.size() <= first_number) return Error(st.line, st.word + " has no diameter");
    tpopt::Cutter cutter;
    double d = 0.0;
    Status s = Number(st, first_number, &d);
    if (!s.ok()) return s;
    cutter.radius_mm = 0.5 * d;
    if (st.word == "TLDATA" && st.args.size() > first_number + 2) {
      s = Number(st, first_number + 2, &cutter.flute_length_mm);
      if (!s.ok()) return s;
    }
    s = cutter.Validate(name_ + ":" + std::to_string(st.line));
    if (!s.ok()) return s;
    path_->cutter = cutter;
    return Status::Ok();
  }

  Status Feed(const Statement& st) {
    for (size_t k = 0; k < st.args.size(); ++k) {
      const std::string word = Upper(st.args[k]);
      if (word == "MMPM" || word.empty()) continue;
      if (word == "IPM" || word == "IPR" || word == "MMPR") {
        return Error(st.line, "FEDRAT unit " + word + " is not supported (MMPM)");
      }
      Status s = Number(st, k, &feed_);
      if (!s.ok()) return s;
      if (!(feed_ > 0)) return Error(st.line, "FEDRAT " + st.args[k] + " must be > 0");
      return Status::Ok();
    }
    return Error(st.line, "FEDRAT has no feed value");
  }

  Status Handle(const Statement& st) {
    if (st.word == "GOTO") return Goto(st);
    if (st.word == "TLDATA") return Cutter(st, 1);  // TLDATA/MILL,d,r,l
    if (st.word == "CUTTER") return Cutter(st, 0);
    if (st.word == "FEDRAT") return Feed(st);
    if (st.word == "RAPID") {
      rapid_next_ = true;
      return Status::Ok();
    }
    if (st.word == "UNITS") {
      if (!st.args.empty() && Upper(st.args[0]) != "MM") {
        return Error(st.line, "UNITS/" + st.args[0] + " is not supported (UNITS/MM)");
      }
      return Status::Ok();
    }
    static const std::set<std::string> kIgnored = {
        "MULTAX", "TOOL PATH", "PAINT", "END-OF-PATH", "FINI", "PARTNO", "LOADTL", "SPINDL",
        "COOLNT", "NURBS", ""};
    if (kIgnored.count(st.word) == 0 && warned_.insert(st.word).second && warnings_) {
      warnings_->push_back(name_ + ":" + std::to_string(st.line) + ": statement '" + st.word +
                           "' is not understood; skipped (warned once)");
    }
    return Status::Ok();
  }

  std::string name_;
  ToolPath* path_;
  std::vector<std::string>* warnings_;
  Eigen::Vector3d axis_ = Eigen::Vector3d::UnitZ();
  double feed_ = 0.0;
  bool rapid_next_ = false;
  std::set<std::string> warned_;
};

}  // namespace

Status ReadAptStream(std::istream& in, const std::string& name, ToolPath* tool_path,
                     std::vector<std::string>* warnings) {
  ToolPath path;
  AptReader reader(name, &path, warnings);
  Status s = reader.Read(in);
  if (!s.ok()) return s;
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
                           " cannot be written (out of order, past the last pose or not finite)");
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

std::string FormatApt(const ToolPath& tool_path, const std::vector<AptCurveSpan>& spans) {
  std::string out;
  out.reserve(64 * tool_path.poses.size() + 256);
  char buf[256];
  out += CommentLine(tool_path.title);
  out += "TOOL PATH/TPOPT\nUNITS/MM\nMULTAX/ON\n";
  if (tool_path.cutter) {
    std::snprintf(buf, sizeof(buf), "TLDATA/MILL,%.6f,0.000000,%.6f\n",
                  2 * tool_path.cutter->radius_mm, tool_path.cutter->flute_length_mm);
    out += buf;
  }
  double feed = -1.0;
  size_t next_span = 0;
  for (size_t i = 0; i < tool_path.poses.size(); ++i) {
    const ToolPose& p = tool_path.poses[i];
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
  Status s = CheckWritable(path, tool_path);
  if (s.ok()) s = CheckSpans(path, tool_path, spans);
  if (!s.ok()) return s;
  return WriteFileAtomically(path, FormatApt(tool_path, spans));
}

}  // namespace tpopt
