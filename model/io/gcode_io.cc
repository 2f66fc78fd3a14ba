#include "model/io/gcode_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include <glog/logging.h>

#include "model/io/atomic_file.h"
#include "model/machine/axis_metrics.h"
#include "model/io/gcode_expression.h"
#include "model/base/invalid_field.h"
#include "model/base/units.h"

namespace tpopt {
namespace {

bool IsBlank(const std::string& line) {
  for (char c : line) {
    if (!std::isspace(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

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

bool GcodeOptions::IsValid(std::string* why) const {
  if (std::isfinite(default_feed_mm_per_min) && default_feed_mm_per_min > 0) return true;
  if (why != nullptr) {
    *why = InvalidField("--feed", default_feed_mm_per_min, "finite and > 0 mm/min");
  }
  return false;
}

Status FormatGcode(const ToolPath& path, const Machine& machine, const GcodeOptions& o,
                   std::string* program) {
  if (std::string why; !o.IsValid(&why)) return Status::Error(why);
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(path, &joints));
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
  RETURN_IF_ERROR(FormatGcode(path, machine, options, &program));
  return WriteFileAtomically(file, program);
}

namespace {

// The block of `program` whose units, style and feed mode each output pose
// is written in: its own, or for a pose a method made, that of the next
// pose kept from the source (the same run's modes: a mode change is a block
// that ends runs).
std::vector<int> ContextBlocks(const Program& program, const ToolPath& output) {
  std::vector<int> context(output.poses.size());
  int next = static_cast<int>(program.blocks.size()) - 1;
  for (size_t j = output.poses.size(); j-- > 0;) {
    if (output.poses[j].source_block >= 0) next = output.poses[j].source_block;
    context[j] = next;
  }
  return context;
}

std::string FeedWord(double f) {
  char word[64];
  std::snprintf(word, sizeof(word), "F%.4f", f);
  return word;
}

}  // namespace

Status FormatGcodeProgram(const ToolPath& input, const ToolPath& output, const Machine& machine,
                          const GcodeOptions& o, std::string* text) {
  CHECK(output.program != nullptr && output.program->format == ProgramFormat::kGcode);
  if (std::string why; !o.IsValid(&why)) return Status::Error(why);
  const Program& program = *output.program;
  std::vector<ProgramItem> items;
  RETURN_IF_ERROR(SpliceProgram(program, input, output, &items));
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(output, &joints));
  const std::vector<int> context = ContextBlocks(program, output);
  std::string out;
  char line[256];
  // The F the controller holds as far as the written program goes, and
  // whether a written move changed it from the source's.
  double written_feed = 0.0;
  bool feed_changed = false;
  for (const ProgramItem& item : items) {
    if (item.block >= 0) {
      const ProgramBlock& block = program.blocks[item.block];
      const double source_feed = item.block > 0 ? program.blocks[item.block - 1].modal_feed : 0.0;
      if (feed_changed && !IsBlank(block.text)) {
        if (!block.inverse_time && source_feed > 0 && source_feed != written_feed) {
          out += FeedWord(source_feed) + "\n";  // what the source's next blocks rely on
        }
        feed_changed = false;
      }
      out += block.text + "\n";
      written_feed = block.modal_feed;
      continue;
    }
    const size_t j = static_cast<size_t>(item.pose);
    const ToolPose& p = output.poses[j];
    const ProgramBlock& block = program.blocks[context[j]];
    const Eigen::Vector3d xyz =
        (block.machine_joints ? Eigen::Vector3d(joints[j].head<3>()) : p.p_w_tip) /
        block.mm_per_unit;
    int n = std::snprintf(line, sizeof(line), "G1 X%.6f Y%.6f Z%.6f A%.6f C%.6f", xyz.x(), xyz.y(),
                          xyz.z(), joints[j][kA] * kRadToDeg, joints[j][kC] * kRadToDeg);
    out.append(line, n);
    double f = 0.0;
    if (block.inverse_time) {
      const double dt_s =
          j > 0 ? SegmentTime(machine, output, joints, j - 1, o.default_feed_mm_per_min) : 0.0;
      f = 60.0 / std::max(dt_s, 1e-6);
    } else if (p.feed_mm_per_min > 0) {
      f = p.feed_mm_per_min / block.mm_per_unit;
    }
    if (f > 0 && (block.inverse_time || f != written_feed)) {
      out += " " + FeedWord(f);
      written_feed = f;
      feed_changed = true;
    }
    if (p.link) out += std::string(" ") + kLinkComment;
    out += '\n';
  }
  if (!program.final_newline && !out.empty()) out.pop_back();
  *text = std::move(out);
  return Status::Ok();
}

Status WriteGcodeProgram(const std::string& file, const ToolPath& input, const ToolPath& output,
                         const Machine& machine, const GcodeOptions& options) {
  std::string text;
  RETURN_IF_ERROR(FormatGcodeProgram(input, output, machine, options, &text));
  return WriteFileAtomically(file, text);
}

namespace {

// Strips ( ) and ; comments and spaces, in upper case; false on an unclosed
// parenthesis.
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

std::string FormatNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The construct an o-word line starts ("O100SUB" -> "sub").
std::string OwordConstruct(const std::string& code) {
  size_t i = 1;
  if (i < code.size() && code[i] == '<') {
    const size_t close = code.find('>', i);
    i = close == std::string::npos ? code.size() : close + 1;
  }
  while (i < code.size() && (std::isdigit(static_cast<unsigned char>(code[i])) || code[i] == '.')) {
    ++i;
  }
  std::string word;
  while (i < code.size() && std::isalpha(static_cast<unsigned char>(code[i]))) {
    word += static_cast<char>(std::tolower(static_cast<unsigned char>(code[i++])));
  }
  return word;
}

// Larger word values are no coordinate, feed or code of a real program.
constexpr double kLargestValue = 1e6;
constexpr long kMostNesting = 256;

constexpr int kAxes = 5;  // X Y Z A C, the indices of JointVector
constexpr int kNoMotion = -1;
constexpr int kOtherMotion = 99;  // canned cycles, G33, G38.x, G5.x

// What one block does besides its axis words, from its G and M words.
struct BlockCodes {
  bool other = false;      // any word a plain cutting move does not carry
  bool axis_data = false;  // axis words are data (G10, G28, G30, G52, G92)
  bool g53 = false;
  bool all_unknown_after = false;  // offsets, tool change, home moves
  bool z_unknown_after = false;    // tool length offset changed
  int length_offset = 0;           // 430, 431, 432 or 490 (G43, G43.1, G43.2, G49)
  bool ends = false;               // M2, M30
};

class GcodeReader {
 public:
  GcodeReader(const std::string& name, const Machine& machine, GcodeStyle style, ToolPath* path,
              std::vector<std::string>* warnings)
      : name_(name), machine_(machine), style_(style), path_(path), warnings_(warnings) {
    program_.format = ProgramFormat::kGcode;
    program_.file = name;
  }

  Status Read(std::istream& in) {
    std::string line, code;
    int n = 0;
    while (std::getline(in, line)) {
      ++n;
      program_.final_newline = !in.eof();
      ProgramBlock block;
      block.line = n;
      block.text = line;
      if (!ended_) {
        if (!StripComments(line, &code)) return Error(n, "unbalanced parenthesis in a comment");
        RETURN_IF_ERROR(Block(code, n, line, &block));
      }
      block.mm_per_unit = scale_;
      block.machine_joints = style_ == GcodeStyle::kJoint;
      block.inverse_time = inverse_time_;
      block.modal_feed = feed_;
      program_.blocks.push_back(std::move(block));
    }
    if (path_->poses.empty()) {
      return Status::Error(name_ +
                           ": no G0/G1 move places all five axes X Y Z A C: the path is empty");
    }
    path_->program = std::make_shared<const Program>(std::move(program_));
    return Status::Ok();
  }

 private:
  Status Error(int line, const std::string& what) const {
    return Status::Error(name_ + ":" + std::to_string(line) + ": " + what);
  }

  void Warn(int line, const std::string& what) {
    if (warned_.insert(what).second && warnings_ != nullptr) {
      warnings_->push_back(name_ + ":" + std::to_string(line) + ": " + what + " (warned once)");
    }
  }

  Status Codes(const std::vector<std::pair<char, double>>& words, int n, BlockCodes* codes) {
    RETURN_IF_ERROR(Tools(words, n));
    for (const auto& [letter, value] : words) {
      if (letter == 'G') {
        RETURN_IF_ERROR(GCode(value, n, codes));
      } else if (letter == 'M') {
        codes->other = true;
        if (value != std::round(value))
          return Error(n, "M" + FormatNumber(value) + " is no M code");
        const int m = static_cast<int>(value);
        if (m == 428) style_ = GcodeStyle::kTcp;
        if (m == 429) style_ = GcodeStyle::kJoint;
        if (m == 2 || m == 30) codes->ends = true;
        if (m == 6) codes->all_unknown_after = true;  // a tool change may move the axes
        if (m == 72) {
          return Error(n,
                       "M72 (restore modal state) is not supported: the modes "
                       "it restores are "
                       "not tracked");
        }
        const bool known = m <= 9 || m == 19 || m == 30 || (m >= 48 && m <= 53) || m == 60 ||
                           (m >= 61 && m <= 71) || m == 73 || (m >= 100 && m <= 199) || m == 428 ||
                           m == 429;
        if (!known) Warn(n, "M" + std::to_string(m) + " is passed through as written");
      } else if (letter != 'X' && letter != 'Y' && letter != 'Z' && letter != 'A' &&
                 letter != 'C' && letter != 'F' && letter != 'N') {
        codes->other = true;
      }
    }
    return Status::Ok();
  }

  // T selects a tool, M6 loads the selected one and M61 Qn makes tool n the
  // loaded one (LinuxCNC runs T before M6 whatever their order on the
  // line): each load is a ToolRecord, and the moves after it take it.
  Status Tools(const std::vector<std::pair<char, double>>& words, int n) {
    bool change = false, set = false;
    double q = -1;
    for (const auto& [letter, value] : words) {
      if (letter == 'T') {
        if (value != std::round(value) || value < 0 || value > 1e9) {
          return Error(n, "T" + FormatNumber(value) + " is no tool number");
        }
        selected_tool_ = static_cast<int>(value);
      }
      if (letter == 'M' && value == 6) change = true;
      if (letter == 'M' && value == 61) set = true;
      if (letter == 'Q') q = value;
    }
    if (set && (q != std::round(q) || q < 0 || q > 1e9)) {
      return Error(n, "M61 needs Q and a tool number, not Q" + FormatNumber(q));
    }
    if (!change && !set) return Status::Ok();
    const int number = set ? static_cast<int>(q) : selected_tool_;
    if (number < 0) return Error(n, "M6 with no tool selected (T)");
    if (number == 0) {
      current_tool_ = -1;  // T0: the spindle is empty
      return Status::Ok();
    }
    ToolRecord tool;
    tool.number = number;
    tool.source_line = n;
    path_->tools.push_back(tool);
    current_tool_ = static_cast<int>(path_->tools.size()) - 1;
    return Status::Ok();
  }

  // G43 [H], G43.1 Z, G43.2 H, G49: the offset the next moves carry
  // (ToolPose::length_offset_*).
  Status LengthOffset(int g, const std::vector<std::pair<char, double>>& words, int n) {
    double h = -1, z = 0;
    for (const auto& [letter, value] : words) {
      if (letter == 'H') h = value;
      if (letter == 'Z') z = value * scale_;
    }
    if (h != -1 && (h != std::round(h) || h < 0 || h > 1e9)) {
      return Error(n, "H" + FormatNumber(h) + " is no tool number");
    }
    if (g == 490) {
      length_offset_tool_ = 0;
      length_offset_mm_ = 0.0;
    } else if (g == 430) {
      const int loaded = current_tool_ < 0 ? 0 : path_->tools[current_tool_].number;
      length_offset_tool_ = h >= 0 ? static_cast<int>(h) : loaded;
      length_offset_mm_ = 0.0;
    } else if (g == 431) {
      length_offset_tool_ = 0;
      length_offset_mm_ = z;
    } else {
      length_offset_tool_ = -1;
    }
    return Status::Ok();
  }

  Status GCode(double value, int n, BlockCodes* codes) {
    const int g = static_cast<int>(std::lround(value * 10));  // G38.2 -> 382
    if (std::abs(value * 10 - g) > 1e-6)
      return Error(n, "G" + FormatNumber(value) + " is no G code");
    if (g != 10) codes->other = true;
    switch (g) {
      case 0:
      case 10:
      case 20:
      case 30:
        motion_ = g / 10;
        return Status::Ok();
      case 50:
      case 51:
      case 52:
      case 53:
      case 330:
      case 331:
      case 730:
      case 760:
      case 382:
      case 383:
      case 384:
      case 385:
      case 810:
      case 820:
      case 830:
      case 840:
      case 850:
      case 860:
      case 870:
      case 880:
      case 890:
        motion_ = kOtherMotion;
        return Status::Ok();
      case 800:
        motion_ = kNoMotion;
        return Status::Ok();
      case 40:
        return Status::Ok();  // dwell: P is its time
      case 100:
      case 280:
      case 281:
      case 300:
      case 301:
      case 520:
      case 920:
      case 921:
      case 922:
      case 923:
        codes->axis_data = true;
        codes->all_unknown_after = true;
        return Status::Ok();
      case 530:
        codes->g53 = true;
        return Status::Ok();
      case 540:
      case 550:
      case 560:
      case 570:
      case 580:
      case 590:
      case 591:
      case 592:
      case 593:
        if (g != coordinate_system_) codes->all_unknown_after = true;
        coordinate_system_ = g;
        return Status::Ok();
      case 430:
      case 431:
      case 432:
      case 490:
        codes->z_unknown_after = true;
        codes->length_offset = g;
        if (g == 431) codes->axis_data = true;  // G43.1's axis words are the offset
        return Status::Ok();
      case 400:
        compensation_ = false;
        return Status::Ok();
      case 410:
      case 411:
      case 420:
      case 421:
        compensation_ = true;
        return Status::Ok();
      case 200:
        scale_ = kMmPerInch;
        return Status::Ok();
      case 210:
        scale_ = 1.0;
        return Status::Ok();
      case 900:
        incremental_ = false;
        return Status::Ok();
      case 910:
        incremental_ = true;
        return Status::Ok();
      case 930:
        inverse_time_ = true;
        per_revolution_ = false;
        return Status::Ok();
      case 940:
        inverse_time_ = false;
        per_revolution_ = false;
        return Status::Ok();
      case 950:
        inverse_time_ = false;
        per_revolution_ = true;
        return Status::Ok();
      case 170:
      case 171:
      case 180:
      case 181:
      case 190:
      case 191:
      case 610:
      case 611:
      case 640:
      case 901:
      case 911:
      case 960:
      case 970:
      case 980:
      case 990:
        return Status::Ok();
      case 70:
      case 80:
        return Error(n, "G" + FormatNumber(value) +
                            " (lathe diameter/radius mode) is not "
                            "supported on an A/C mill");
      default:
        return Error(n, "G" + FormatNumber(value) + " is not a G code tpopt reads");
    }
  }

  // Splits a block into letter/value pairs and parameter assignments.
  Status Words(const std::string& code, int n, std::vector<std::pair<char, double>>* words,
               std::vector<std::pair<std::string, double>>* assignments) {
    size_t i = 0;
    while (i < code.size()) {
      if (code[i] == '#') {
        std::pair<std::string, double> assignment;
        Status s = parameters_.ReadAssignment(code, &i, &assignment);
        if (!s.ok()) return Error(n, s.message());
        assignments->push_back(assignment);
        continue;
      }
      const char letter = code[i++];
      if (!std::isalpha(static_cast<unsigned char>(letter))) {
        return Error(n, std::string("unexpected '") + letter + "'");
      }
      if (letter == 'B' || letter == 'U' || letter == 'V' || letter == 'W') {
        return Error(n, std::string("word '") + letter + "': the machine has no " + letter +
                            " axis (an A/C machine has X Y Z A C); the program "
                            "is for another "
                            "machine");
      }
      if (std::string("DFGHIJKLMNPQRSTXYZAC").find(letter) == std::string::npos) {
        return Error(n, std::string("word '") + letter + "' is not LinuxCNC G-code");
      }
      double value = 0.0;
      Status s = parameters_.ReadValue(code, &i, &value);
      if (!s.ok()) return Error(n, std::string("word ") + letter + ": " + s.message());
      if (!(std::abs(value) <= kLargestValue)) {
        return Error(n, std::string("word ") + letter + " value " + FormatNumber(value) +
                            " is out of range");
      }
      for (const auto& word : *words) {
        if (word.first == letter && std::string("XYZACF").find(letter) != std::string::npos) {
          return Error(n, std::string("word ") + letter + " appears twice");
        }
      }
      words->emplace_back(letter, value);
    }
    return Status::Ok();
  }

  // Reads block `code` (comments and spaces stripped) of source `line` n
  // into `block` and, if it is a move that places every axis, a pose.
  Status Block(const std::string& code, int n, const std::string& line, ProgramBlock* block) {
    if (code.empty() || code == "%") {
      // A comment stops a run where it stands; a blank line does not.
      if (!IsBlank(line)) Break();
      return Status::Ok();
    }
    if (code[0] == '/') {
      return Error(n,
                   "block delete '/' is not supported: whether the block runs is the "
                   "operator's switch");
    }
    if (code[0] == 'O') {
      const std::string construct = OwordConstruct(code);
      return Error(n, "o-word " +
                          (construct.empty() ? std::string("line") : "'" + construct + "'") +
                          " (subroutines, calls, if/while/repeat) is not "
                          "supported; expand it "
                          "into plain moves");
    }
    // Expressions and parameters are read recursively: a bound on their
    // count bounds the depth (no real block comes near it).
    const auto nested = std::count(code.begin(), code.end(), '[') +
                        std::count(code.begin(), code.end(), '#');
    if (nested > kMostNesting) {
      return Error(n, "the block has " + std::to_string(nested) + " brackets and parameters, " +
                          "more than the " + std::to_string(kMostNesting) + " tpopt reads");
    }
    std::vector<std::pair<char, double>> words;
    std::vector<std::pair<std::string, double>> assignments;
    RETURN_IF_ERROR(Words(code, n, &words, &assignments));
    BlockCodes codes;
    RETURN_IF_ERROR(Codes(words, n, &codes));
    std::map<char, double> axes;
    for (const auto& [letter, value] : words) {
      if (std::string("XYZAC").find(letter) != std::string::npos) axes[letter] = value;
      if (letter == 'F') {
        if (!(value > 0)) return Error(n, "F" + FormatNumber(value) + " must be > 0");
        feed_ = value;
      }
    }
    for (const auto& [key, value] : assignments) parameters_.Set(key, value);
    if (!assignments.empty()) codes.other = true;
    if (!axes.empty() && !codes.axis_data) {
      RETURN_IF_ERROR(Motion(axes, codes, n, line.find(kLinkComment) != std::string::npos, block));
    } else {
      Break();
    }
    if (codes.all_unknown_after) std::fill(known_, known_ + kAxes, false);
    if (codes.z_unknown_after) known_[2] = false;
    if (codes.length_offset != 0) {
      RETURN_IF_ERROR(LengthOffset(codes.length_offset, words, n));
    }
    if (codes.ends) ended_ = true;
    return Status::Ok();
  }

  Status Motion(const std::map<char, double>& axes, const BlockCodes& codes, int n, bool link,
                ProgramBlock* block) {
    if (motion_ == kNoMotion) return Error(n, "axis words with no motion mode (G0-G3) in effect");
    bool given[kAxes] = {false, false, false, false, false};
    for (const auto& [letter, value] : axes) {
      const int k = letter == 'X'   ? 0
                    : letter == 'Y' ? 1
                    : letter == 'Z' ? 2
                    : letter == 'A' ? 3
                                    : 4;
      const double v = k < 3 ? value * scale_ : value / kRadToDeg;
      given[k] = true;
      if (!incremental_) {
        position_[k] = v;
        known_[k] = true;
      } else {
        position_[k] += v;  // meaningful only where the axis was known
      }
    }
    if (codes.g53 || motion_ == kOtherMotion) {
      // Machine coordinates, or a cycle whose end this reader does not
      // model: written as they are, and the axes they move are unknown
      // until the program sets them again.
      for (int k = 0; k < kAxes; ++k) {
        if (given[k] || motion_ == kOtherMotion) known_[k] = false;
      }
      Break();
      return Status::Ok();
    }
    if (!std::all_of(known_, known_ + kAxes, [](bool k) { return k; })) {
      Break();  // an axis never set stays unset: written as it is
      return Status::Ok();
    }
    ToolPose pose;
    pose.rapid = motion_ == 0;
    pose.link = motion_ == 1 && link;
    pose.held = pending_break_ || codes.other || motion_ >= 2 || compensation_ || per_revolution_;
    pose.source_line = n;
    pose.tool = current_tool_;
    pose.length_offset_tool = length_offset_tool_;
    pose.length_offset_mm = length_offset_mm_;
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
    pose.source_block = static_cast<int>(program_.blocks.size());
    block->pose = static_cast<int>(path_->poses.size());
    block->replaceable =
        motion_ == 1 && !codes.other && !incremental_ && !compensation_ && !per_revolution_;
    // A verbatim move starts where the pose before it is: its modal axes,
    // its arc centre and the other words on its line need that pose as
    // programmed. Only an absolute straight move that gives every axis
    // does not.
    const bool self_contained = !incremental_ && motion_ <= 1 && !codes.other &&
                                std::all_of(given, given + kAxes, [](bool g) { return g; });
    if (!block->replaceable && !self_contained && !path_->poses.empty()) {
      path_->poses.back().held = true;
    }
    path_->poses.push_back(pose);
    pending_break_ = false;
    return Status::Ok();
  }

  // A block without a pose stops the run where it stands: the pose before
  // it is where the program put the tool when the block runs (and the
  // block's own modal axes start there), and the move after it is kept.
  void Break() {
    if (!path_->poses.empty()) path_->poses.back().held = true;
    pending_break_ = true;
  }

  // mm/min of the move into `pose`; inverse time F is 1 / minutes.
  double FeedFor(const ToolPose& pose) const {
    if (per_revolution_) return 0.0;
    if (!inverse_time_ || feed_ <= 0) return feed_ * scale_;
    if (path_->poses.empty()) return 0.0;
    const double length = (pose.p_w_tip - path_->poses.back().p_w_tip).norm();
    return length * feed_;
  }

  std::string name_;
  const Machine& machine_;
  GcodeStyle style_;
  ToolPath* path_;
  std::vector<std::string>* warnings_;
  std::set<std::string> warned_;
  Program program_;
  GcodeParameters parameters_;
  double position_[kAxes] = {0, 0, 0, 0, 0};  // mm and rad
  bool known_[kAxes] = {false, false, false, false, false};
  int motion_ = kNoMotion;
  int coordinate_system_ = 540;  // G54, LinuxCNC's default
  double scale_ = 1.0;
  bool incremental_ = false;
  bool inverse_time_ = false;
  bool per_revolution_ = false;
  bool compensation_ = false;
  bool ended_ = false;
  // A block without a pose came after the last pose: the next one is held.
  bool pending_break_ = false;
  double feed_ = 0.0;  // as written: units/min, or 1/min in G93
  int selected_tool_ = -1;  // the last T word
  int current_tool_ = -1;   // index into path_->tools of the loaded tool
  int length_offset_tool_ = 0;     // ToolPose::length_offset_tool
  double length_offset_mm_ = 0.0;  // G43.1's offset, mm
};

}  // namespace

Status ReadGcodeStream(std::istream& in, const std::string& name, const Machine& machine,
                       GcodeStyle style, ToolPath* path, std::vector<std::string>* warnings) {
  ToolPath out;
  GcodeReader reader(name, machine, style, &out, warnings);
  RETURN_IF_ERROR(reader.Read(in));
  *path = std::move(out);
  return Status::Ok();
}

Status ReadGcode(const std::string& file, const Machine& machine, GcodeStyle style, ToolPath* path,
                 std::vector<std::string>* warnings) {
  std::ifstream in(file);
  if (!in) return Status::Error(file + ": cannot open file");
  return ReadGcodeStream(in, file, machine, style, path, warnings);
}

}  // namespace tpopt
