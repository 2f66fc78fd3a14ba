#include "model/io/linuxcnc_tool_table.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace tpopt {

Status ParseLinuxCncToolTable(std::istream& in, const std::string& name,
                              LinuxCncToolTable* table) {
  table->clear();
  std::string text;
  int line = 0;
  bool any_tool = false;
  while (std::getline(in, text)) {
    ++line;
    const size_t semicolon = text.find(';');
    const std::string words = text.substr(0, semicolon);
    std::string comment = semicolon == std::string::npos ? "" : text.substr(semicolon + 1);
    const std::string at = name + ":" + std::to_string(line) + ": ";
    std::istringstream tokens(words);
    std::string token;
    LinuxCncTool tool;
    tool.line = line;
    bool any = false, have_t = false;
    while (tokens >> token) {
      any = true;
      const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(token[0])));
      if (std::string("TPXYZABCUVWDIJQ").find(letter) == std::string::npos) {
        return Status::Error(at + "word '" + token + "' is not a tool table word (T P X Y Z A B C "
                                                     "U V W D I J Q)");
      }
      const std::string number = token.substr(1);
      if (!any_tool && words.find("POC") != std::string::npos) {
        return Status::Error(at + "'" + text + "' heads an old-style tool table (columns under "
                             "a header), which tpopt does not read: save it from LinuxCNC's "
                             "tooledit to write it as T P Z D words");
      }
      char* end = nullptr;
      const double value = number.empty() ? NAN : std::strtod(number.c_str(), &end);
      if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value)) {
        return Status::Error(at + "word '" + token + "': '" + number + "' is not a number");
      }
      const bool integer = letter == 'T' || letter == 'P' || letter == 'Q';
      if (integer && (value != std::round(value) || std::abs(value) > 1e9)) {
        return Status::Error(at + "word '" + token + "': " + letter + " takes a whole number");
      }
      if ((letter == 'T' || letter == 'D' || letter == 'P') && value < 0) {
        return Status::Error(at + "word '" + token + "': " + letter + " must be >= 0");
      }
      if (letter == 'T') {
        tool.number = static_cast<int>(value);
        have_t = true;
      } else if (letter == 'P') {
        tool.pocket = static_cast<int>(value);
      } else if (letter == 'D') {
        tool.diameter_mm = value;
      } else if (letter == 'Z') {
        tool.length_offset_mm = value;
      }
    }
    if (!any) continue;  // blank, or a comment alone
    any_tool = true;
    if (!have_t) {
      return Status::Error(at + "'" + text + "' names no tool (T word)");
    }
    const size_t b = comment.find_first_not_of(" \t");
    tool.comment = b == std::string::npos ? "" : comment.substr(b);
    while (!tool.comment.empty() && std::isspace(static_cast<unsigned char>(tool.comment.back()))) {
      tool.comment.pop_back();
    }
    const auto [it, inserted] = table->emplace(tool.number, tool);
    if (!inserted) {
      return Status::Error(at + "tool T" + std::to_string(tool.number) +
                           " is listed twice (line " + std::to_string(it->second.line) + ")");
    }
  }
  return Status::Ok();
}

Status ReadLinuxCncToolTable(const std::string& path, LinuxCncToolTable* table) {
  std::ifstream in(path);
  if (!in) return Status::Error(path + ": cannot open the tool table");
  return ParseLinuxCncToolTable(in, path, table);
}

Status SizeToolsFromTable(const LinuxCncToolTable& table, const std::string& table_name,
                          double flute_length_mm, ToolPath* path) {
  for (ToolRecord& tool : path->tools) {
    const auto it = table.find(tool.number);
    if (it == table.end()) {
      return Status::Error("line " + std::to_string(tool.source_line) + ": tool T" +
                           std::to_string(tool.number) + " is not in the tool table " +
                           table_name);
    }
    if (it->second.diameter_mm > 0) {
      tool.cutter = Cutter{it->second.diameter_mm / 2, flute_length_mm, 0.0};
    }
  }
  for (ToolPose& pose : path->poses) {
    if (pose.length_offset_tool == -1) {
      return Status::Error("line " + std::to_string(pose.source_line) +
                           ": the move is under G43.2, an added tool length offset, which "
                           "tpopt does not apply");
    }
    if (pose.length_offset_tool == 0) continue;
    const auto it = table.find(pose.length_offset_tool);
    if (it == table.end()) {
      return Status::Error("line " + std::to_string(pose.source_line) + ": G43 H" +
                           std::to_string(pose.length_offset_tool) + ": tool T" +
                           std::to_string(pose.length_offset_tool) + " is not in the tool table " +
                           table_name);
    }
    pose.length_offset_mm += it->second.length_offset_mm;
  }
  for (const ToolPose& pose : path->poses) {
    if (pose.rapid || pose.tool < 0) continue;
    if (path->tools[pose.tool].cutter) path->cutter = path->tools[pose.tool].cutter;
    break;
  }
  return Status::Ok();
}

}  // namespace tpopt
