#include "model/io/linuxcnc_ini.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "model/base/units.h"

namespace tpopt {
namespace {

constexpr char kKins[] = "xyzac-trt-kins";

struct Entry {
  std::string value;
  int line = 0;
};

// Section -> key -> entries in file order (HALCMD, HALFILE repeat).
using Ini = std::map<std::string, std::map<std::string, std::vector<Entry>>>;

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::string Lower(std::string s) {
  for (char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

Status Parse(std::istream& in, const std::string& name, Ini* ini) {
  std::string text, section;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    const std::string t = Trim(text);
    if (t.empty() || t[0] == '#' || t[0] == ';') continue;
    if (t[0] == '[') {
      const auto close = t.find(']');
      if (close == std::string::npos) {
        return Status::Error(name + ":" + std::to_string(line) +
                             ": section header '" + t + "' has no ']'");
      }
      section = t.substr(1, close - 1);
      continue;
    }
    const auto eq = t.find('=');
    if (eq == std::string::npos || section.empty())
      continue;  // LinuxCNC ignores these too
    (*ini)[section][Trim(t.substr(0, eq))].push_back(
        {Trim(t.substr(eq + 1)), line});
  }
  return Status::Ok();
}

const Entry* Find(const Ini& ini, const std::string& section,
                  const std::string& key) {
  const auto s = ini.find(section);
  if (s == ini.end()) return nullptr;
  const auto k = s->second.find(key);
  if (k == s->second.end() || k->second.empty()) return nullptr;
  return &k->second.front();
}

Status ToNumber(const std::string& where, const std::string& text,
                double* value) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) {
    return Status::Error(where + " = '" + text + "' is not a number");
  }
  *value = v;
  return Status::Ok();
}

std::string Where(const std::string& name, const Entry& e,
                  const std::string& section, const std::string& key) {
  return name + ":" + std::to_string(e.line) + ": [" + section + "] " + key;
}

// Tightens `limits` (mm or rad) by the four keys of `section`, if present.
Status TightenBy(const Ini& ini, const std::string& name,
                 const std::string& section, double scale, AxisLimits* limits) {
  struct Key {
    const char* key;
    double* field;
    bool is_min;
  };
  const Key keys[] = {{"MIN_LIMIT", &limits->min, true},
                      {"MAX_LIMIT", &limits->max, false},
                      {"MAX_VELOCITY", &limits->max_velocity, false},
                      {"MAX_ACCELERATION", &limits->max_acceleration, false}};
  for (const Key& k : keys) {
    const Entry* e = Find(ini, section, k.key);
    if (e == nullptr) continue;
    double v = 0;
    const std::string where = Where(name, *e, section, k.key);
    RETURN_IF_ERROR(ToNumber(where, e->value, &v));
    if (k.field != &limits->min && k.field != &limits->max && !(v > 0)) {
      return Status::Error(where + " = " + e->value + " must be > 0");
    }
    v *= scale;
    *k.field = k.is_min ? std::max(*k.field, v) : std::min(*k.field, v);
  }
  return Status::Ok();
}

struct HalLine {
  std::string text;
  std::string where;  // file:line
};

// The HAL command lines: HALCMD values, then the lines of the plain .hal
// files HALFILE names (LIB: files and Tcl scripts are LinuxCNC's own).
Status HalLines(const Ini& ini, const std::string& name,
                const std::string& folder, std::vector<HalLine>* lines) {
  const auto hal = ini.find("HAL");
  if (hal == ini.end()) return Status::Ok();
  const auto files = hal->second.find("HALFILE");
  if (files != hal->second.end() && !folder.empty()) {
    for (const Entry& e : files->second) {
      std::istringstream words(e.value);
      std::string file;
      words >> file;
      if (file.rfind("LIB:", 0) == 0 || Lower(file).size() < 4 ||
          Lower(file).substr(Lower(file).size() - 4) != ".hal") {
        continue;
      }
      const std::string path = file[0] == '/' ? file : folder + "/" + file;
      std::ifstream in(path);
      if (!in) {
        return Status::Error(Where(name, e, "HAL", "HALFILE") + " = " + file +
                             ": cannot open " + path);
      }
      std::string text;
      for (int line = 1; std::getline(in, text); ++line) {
        lines->push_back({text, path + ":" + std::to_string(line)});
      }
    }
  }
  const auto cmds = hal->second.find("HALCMD");
  if (cmds != hal->second.end()) {
    for (const Entry& e : cmds->second) {
      lines->push_back({e.value, name + ":" + std::to_string(e.line)});
    }
  }
  return Status::Ok();
}

// Values that setp and sets give the kinematics component's pins.
Status KinematicsPins(
    const std::vector<HalLine>& lines,
    std::map<std::string, std::pair<double, std::string>>* pins) {
  std::map<std::string, std::vector<std::string>> signal_pins;
  std::vector<std::vector<std::string>> sets;
  std::vector<std::string> sets_where;
  for (const HalLine& l : lines) {
    std::istringstream in(l.text.substr(0, l.text.find('#')));
    std::vector<std::string> w;
    for (std::string word; in >> word;) w.push_back(word);
    if (w.size() >= 2 && w[0] == "net") {
      for (size_t i = 2; i < w.size(); ++i) {
        if (w[i] != "<=" && w[i] != "=>" && w[i] != "<=>")
          signal_pins[w[1]].push_back(w[i]);
      }
    } else if (w.size() == 3 && (w[0] == "setp" || w[0] == "sets")) {
      sets.push_back(w);
      sets_where.push_back(l.where);
    }
  }
  for (size_t i = 0; i < sets.size(); ++i) {
    const std::vector<std::string>& w = sets[i];
    std::vector<std::string> targets;
    if (w[0] == "setp") {
      targets.push_back(w[1]);
    } else if (signal_pins.count(w[1])) {
      targets = signal_pins[w[1]];
    }
    for (const std::string& pin : targets) {
      if (pin.rfind(std::string(kKins) + ".", 0) != 0) continue;
      double v = 0;
      RETURN_IF_ERROR(ToNumber(sets_where[i] + ": " + w[0] + " " + w[1], w[2], &v));
      (*pins)[pin.substr(sizeof(kKins))] = {v, sets_where[i]};
    }
  }
  return Status::Ok();
}

}  // namespace

bool IsLinuxCncIni(const std::string& path) {
  const std::string p = Lower(path);
  return p.size() >= 4 && p.substr(p.size() - 4) == ".ini";
}

Status ParseLinuxCncIni(std::istream& in, const std::string& name,
                        const std::string& folder, Machine* machine) {
  Ini ini;
  Status s = Parse(in, name, &ini);
  if (!s.ok()) return s;
  const Entry* kins = Find(ini, "KINS", "KINEMATICS");
  if (kins == nullptr)
    return Status::Error(name + ": [KINS] KINEMATICS is missing");
  std::istringstream kins_words(kins->value);
  std::string module;
  kins_words >> module;
  if (module != kKins) {
    return Status::Error(Where(name, *kins, "KINS", "KINEMATICS") + " = " +
                         kins->value + ": only " + kKins + " is supported");
  }
  for (const auto& [key, want] :
       {std::pair<const char*, const char*>{"COORDINATES", "XYZAC"},
        {"LINEAR_UNITS", "mm"},
        {"ANGULAR_UNITS", "deg"}}) {
    const Entry* e = Find(ini, "TRAJ", key);
    std::string value = e == nullptr ? "" : e->value;
    value.erase(std::remove_if(value.begin(), value.end(), ::isspace),
                value.end());
    if (e != nullptr && Lower(value) != Lower(want)) {
      return Status::Error(Where(name, *e, "TRAJ", key) + " = " + e->value +
                           ": only " + want + " is supported");
    }
  }
  Machine m;
  const Entry* title = Find(ini, "EMC", "MACHINE");
  m.name = title != nullptr ? title->value : name;
  for (int axis = 0; axis < 5; ++axis) {
    const double scale = axis >= kA ? kDegToRad : 1.0;
    AxisLimits& l = m.limits[axis];
    s = TightenBy(ini, name, "JOINT_" + std::to_string(axis), scale, &l);
    if (s.ok())
      s = TightenBy(ini, name, std::string("AXIS_") + kAxisNames[axis], scale,
                    &l);
    if (!s.ok()) return s;
    if (l.min > l.max) {
      std::ostringstream err;
      err << name << ": axis " << kAxisNames[axis] << ": MIN_LIMIT "
          << l.min / scale << " is above MAX_LIMIT " << l.max / scale
          << " ([JOINT_" << axis << "] and [AXIS_" << kAxisNames[axis]
          << "] together)";
      return Status::Error(err.str());
    }
  }
  std::vector<HalLine> lines;
  s = HalLines(ini, name, folder, &lines);
  std::map<std::string, std::pair<double, std::string>> pins;
  if (s.ok()) s = KinematicsPins(lines, &pins);
  if (!s.ok()) return s;
  auto pin = [&](const char* key, double* field) {
    const auto it = pins.find(key);
    if (it != pins.end()) *field = it->second.first;
  };
  pin("x-rot-point", &m.kinematics.rotary_pivot_mm.x());
  pin("y-rot-point", &m.kinematics.rotary_pivot_mm.y());
  pin("z-rot-point", &m.kinematics.rotary_pivot_mm.z());
  pin("y-offset", &m.kinematics.y_offset_mm);
  pin("z-offset", &m.kinematics.z_offset_mm);
  pin("tool-offset", &m.kinematics.tool_length_mm);
  *machine = m;
  return Status::Ok();
}

Status ReadLinuxCncIni(const std::string& path, Machine* machine) {
  std::ifstream in(path);
  if (!in) return Status::Error(path + ": cannot open the LinuxCNC INI file");
  const auto slash = path.find_last_of('/');
  const std::string folder =
      slash == std::string::npos ? "." : path.substr(0, slash);
  return ParseLinuxCncIni(in, path, folder, machine);
}

Status LinuxCncIniToolTable(const std::string& path, std::string* table) {
  table->clear();
  std::ifstream in(path);
  if (!in) return Status::Error(path + ": cannot open the LinuxCNC INI file");
  Ini ini;
  Status s = Parse(in, path, &ini);
  if (!s.ok()) return s;
  const Entry* e = Find(ini, "EMCIO", "TOOL_TABLE");
  if (e == nullptr || e->value.empty()) return Status::Ok();
  const auto slash = path.find_last_of('/');
  *table = e->value[0] == '/' || slash == std::string::npos
               ? e->value
               : path.substr(0, slash + 1) + e->value;
  return Status::Ok();
}

}  // namespace tpopt
