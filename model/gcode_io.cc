#include "model/gcode_io.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "model/atomic_file.h"
#include "model/axis_metrics.h"

namespace tpopt {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kMmPerInch = 25.4;

// Text safe inside a ( ) comment: LinuxCNC rejects nested parentheses.
std::string CommentText(std::string text) {
  for (char& c : text) {
    if (c == '(') c = '[';
    if (c == ')') c = ']';
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

std::string Header(const ToolPath& path, const GcodeOptions& o, const Machine& machine) {
  std::ostringstream h;
  h << "(tpopt program: " << CommentText(path.title.empty() ? "tool path" : path.title) << ")\n";
  h << "(units mm, degrees; style " << (o.style == GcodeStyle::kTcp ? "tcp" : "joint")
    << "; machine " << CommentText(machine.name) << ")\n";
  if (path.cutter) {
    h << "(tool: flat end mill D" << 2 * path.cutter->radius_mm << " flute "
      << path.cutter->flute_length_mm << ")\n";
  }
  h << "(" << path.poses.size() << " poses)\n";
  h << "G21 G90 G17 G40 G49 G80\n" << (o.inverse_time ? "G93\n" : "G94\n");
  if (!o.preamble.empty()) h << o.preamble << "\n";
  return h.str();
}

}  // namespace

Status FormatGcode(const ToolPath& path, const Machine& machine, const GcodeOptions& o,
                   std::string* program) {
  std::vector<JointVector> joints;
  Status s = machine.AssignJoints(path, &joints);
  if (!s.ok()) return s;
  std::string out = Header(path, o, machine);
  char line[256];
  double last_feed = -1.0;
  for (size_t i = 0; i < path.poses.size(); ++i) {
    const ToolPose& p = path.poses[i];
    const Eigen::Vector3d xyz =
        o.style == GcodeStyle::kTcp ? p.p_w_tip : Eigen::Vector3d(joints[i].head<3>());
    const bool rapid = p.rapid || i == 0;  // the first move positions
    int n = std::snprintf(line, sizeof(line), "%s X%.6f Y%.6f Z%.6f A%.6f C%.6f",
                          rapid ? "G0" : "G1", xyz.x(), xyz.y(), xyz.z(),
                          joints[i][kA] * kRadToDeg, joints[i][kC] * kRadToDeg);
    if (!rapid) {
      double f = p.feed_mm_per_min > 0 ? p.feed_mm_per_min : o.default_feed_mm_per_min;
      if (o.inverse_time) {
        const double dt_s = SegmentTime(machine, path, joints, i - 1, o.default_feed_mm_per_min);
        f = 60.0 / std::max(dt_s, 1e-6);
      }
      if (o.inverse_time || f != last_feed) {
        n += std::snprintf(line + n, sizeof(line) - n, " F%.4f", f);
        last_feed = f;
      }
    } else if (o.inverse_time) {
      last_feed = -1.0;
    }
    out.append(line, n);
    if (p.link && !rapid) out += std::string(" ") + kLinkComment;
    out += '\n';
  }
  if (!o.postamble.empty()) out += o.postamble + "\n";
  out += "M2\n";
  *program = std::move(out);
  return Status::Ok();
}

Status WriteGcode(const std::string& file, const ToolPath& path, const Machine& machine,
                  const GcodeOptions& options) {
  std::string program;
  Status s = FormatGcode(path, machine, options, &program);
  if (!s.ok()) return s;
  return WriteFileAtomically(file, program);
}

namespace {

// Strips ( ) and ; comments; false on an unclosed parenthesis.
bool StripComments(const std::string& line, std::string* code) {
  code->clear();
  int depth = 0;
  for (char c : line) {
    if (depth == 0 && c == ';') break;
    if (c == '(') {
      ++depth;
    } else if (c == ')') {
      if (depth == 0) return false;
      --depth;
    } else if (depth == 0 && !std::isspace(static_cast<unsigned char>(c))) {
      *code += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
  }
  return depth == 0;
}

class GcodeReader {
 public:
  GcodeReader(const std::string& name, const Machine& machine, GcodeStyle style, ToolPath* path,
              std::vector<std::string>* warnings)
      : name_(name), machine_(machine), style_(style), path_(path), warnings_(warnings) {}

  Status Read(std::istream& in) {
    std::string line, code;
    for (int n = 1; std::getline(in, line); ++n) {
      if (!StripComments(line, &code)) return Error(n, "unbalanced parenthesis in a comment");
      if (code.empty() || code == "%") continue;
      Status s = Block(code, n, line.find(kLinkComment) != std::string::npos);
      if (!s.ok()) return s;
    }
    if (path_->poses.empty()) return Status::Error(name_ + ": no G0/G1 move: the path is empty");
    return Status::Ok();
  }

 private:
  Status Error(int line, const std::string& what) const {
    return Status::Error(name_ + ":" + std::to_string(line) + ": " + what);
  }

  void Warn(int line, const std::string& word) {
    if (warned_.insert(word).second && warnings_ != nullptr) {
      warnings_->push_back(name_ + ":" + std::to_string(line) + ": word '" + word +
                           "' is not understood; ignored (warned once)");
    }
  }

  // Splits "G1X1.5Y2" into letter/value pairs.
  Status Words(const std::string& code, int n, std::vector<std::pair<char, double>>* words) {
    size_t i = 0;
    while (i < code.size()) {
      const char letter = code[i++];
      if (!std::isalpha(static_cast<unsigned char>(letter))) {
        return Error(n, std::string("unexpected '") + letter + "'");
      }
      // G-code numbers are [+-]digits[.digits]: no exponents, no hex (a
      // plain strtod would read "G0X1" as the hexadecimal 0x1).
      size_t j = i;
      if (j < code.size() && (code[j] == '+' || code[j] == '-')) ++j;
      const size_t digits_start = j;
      while (j < code.size() && (std::isdigit(static_cast<unsigned char>(code[j])) || code[j] == '.')) {
        ++j;
      }
      const std::string number = code.substr(i, j - i);
      if (j == digits_start || number.find('.') != number.rfind('.')) {
        return Error(n, std::string("word ") + letter + " has no valid number ('" + number + "')");
      }
      const double value = std::strtod(number.c_str(), nullptr);
      if (std::abs(value) > 1e6) {
        return Error(n, std::string("word ") + letter + " value " + number + " is out of range");
      }
      i = j;
      words->emplace_back(letter, value);
    }
    return Status::Ok();
  }

  // `link`: the line carries kLinkComment.
  Status Block(const std::string& code, int n, bool link) {
    std::vector<std::pair<char, double>> words;
    Status s = Words(code, n, &words);
    if (!s.ok()) return s;
    std::map<char, double> axes;
    bool has_feed = false;
    double feed = 0.0;
    for (const auto& [letter, value] : words) {
      const int number = static_cast<int>(std::lround(value * 10));  // G38.2 -> 382
      if (letter == 'G') {
        switch (number) {
          case 0: motion_ = 0; break;
          case 10: motion_ = 1; break;
          case 20: case 30:
            return Error(n, "arcs (G2/G3) are not supported; post the program with lines");
          case 200: scale_ = kMmPerInch; break;
          case 210: scale_ = 1.0; break;
          case 900: incremental_ = false; break;
          case 910: incremental_ = true; break;
          case 930: inverse_time_ = true; break;
          case 940: inverse_time_ = false; break;
          case 170: case 400: case 490: case 800: case 540: case 610: case 640: case 641: break;
          default: Warn(n, "G" + FormatNumber(value));
        }
      } else if (letter == 'M') {
        if (number == 4280) style_ = GcodeStyle::kTcp;
        else if (number == 4290) style_ = GcodeStyle::kJoint;
        else if (number == 20 || number == 300) break;
        else if (!(number == 30 || number == 40 || number == 50 || number == 60 ||
                   number == 70 || number == 80 || number == 90)) {
          Warn(n, "M" + FormatNumber(value));
        }
      } else if (std::string("XYZAC").find(letter) != std::string::npos) {
        axes[letter] = value;
      } else if (letter == 'F') {
        has_feed = true;
        feed = value;
      } else if (letter != 'N' && letter != 'S' && letter != 'T') {
        Warn(n, std::string(1, letter));
      }
    }
    if (has_feed) {
      if (!(feed > 0)) return Error(n, "F" + FormatNumber(feed) + " must be > 0");
      feed_ = feed;
    }
    if (axes.empty()) return Status::Ok();
    if (motion_ < 0) return Error(n, "axis words before any G0/G1");
    return Move(axes, n, link);
  }

  Status Move(const std::map<char, double>& axes, int n, bool link) {
    for (const auto& [letter, value] : axes) {
      const int k = letter == 'X' ? 0 : letter == 'Y' ? 1 : letter == 'Z' ? 2 : letter == 'A' ? 3 : 4;
      const double v = k < 3 ? value * scale_ : value / kRadToDeg;
      position_[k] = incremental_ ? position_[k] + v : v;
    }
    ToolPose pose;
    pose.rapid = motion_ == 0;
    pose.link = !pose.rapid && link;
    pose.source_line = n;
    const double a = position_[3], c = position_[4];
    if (style_ == GcodeStyle::kTcp) {
      pose.p_w_tip = Eigen::Vector3d(position_[0], position_[1], position_[2]);
      pose.a_w = AnglesToAxis(a, c);
    } else {
      JointVector j;
      j << position_[0], position_[1], position_[2], a, c;
      machine_.ToWorkpiece(j, &pose.p_w_tip, &pose.a_w);
    }
    pose.programmed = RotaryJoints{a, c};
    pose.feed_mm_per_min = FeedFor(pose);
    path_->poses.push_back(pose);
    return Status::Ok();
  }

  // mm/min of the move into `pose`; inverse time F is 1 / minutes.
  double FeedFor(const ToolPose& pose) const {
    if (!inverse_time_ || feed_ <= 0) return feed_ * scale_;
    if (path_->poses.empty()) return 0.0;
    const double length = (pose.p_w_tip - path_->poses.back().p_w_tip).norm();
    return length * feed_;
  }

  static std::string FormatNumber(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }

  std::string name_;
  const Machine& machine_;
  GcodeStyle style_;
  ToolPath* path_;
  std::vector<std::string>* warnings_;
  std::set<std::string> warned_;
  double position_[5] = {0, 0, 0, 0, 0};  // mm and rad
  int motion_ = -1;
  double scale_ = 1.0;
  bool incremental_ = false;
  bool inverse_time_ = false;
  double feed_ = 0.0;
};

}  // namespace

Status ReadGcodeStream(std::istream& in, const std::string& name, const Machine& machine,
                       GcodeStyle style, ToolPath* path, std::vector<std::string>* warnings) {
  ToolPath out;
  GcodeReader reader(name, machine, style, &out, warnings);
  Status s = reader.Read(in);
  if (!s.ok()) return s;
  *path = std::move(out);
  return Status::Ok();
}

Status ReadGcode(const std::string& file, const Machine& machine, GcodeStyle style,
                 ToolPath* path, std::vector<std::string>* warnings) {
  std::ifstream in(file);
  if (!in) return Status::Error(file + ": cannot open file");
  return ReadGcodeStream(in, file, machine, style, path, warnings);
}

}  // namespace tpopt
