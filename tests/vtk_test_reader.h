// A small reader for the two VTK poly data files tpopt writes, so tests can
// parse an export back and compare it with what went in. It checks what
// ParaView relies on: well-formed XML (every tag closed in order, quoted
// attributes) for .vtp, and the legacy keywords with their counts for .vtk.
#ifndef TPOPT_TESTS_VTK_TEST_READER_H_
#define TPOPT_TESTS_VTK_TEST_READER_H_

#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace tpopt::testing {

struct ParsedPolyData {
  std::vector<double> points;  // x, y, z, x, y, z, ...
  std::vector<std::vector<int>> lines, polys;
  std::map<std::string, std::vector<double>> point_scalars;
  size_t point_count() const { return points.size() / 3; }
};

template <typename T>
std::vector<T> Numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<T> out;
  for (T v; in >> v;) out.push_back(v);
  return out;
}

// Cells from VTK XML connectivity and offsets arrays.
inline std::vector<std::vector<int>> CellsFromOffsets(const std::vector<int>& connectivity,
                                                      const std::vector<int>& offsets) {
  std::vector<std::vector<int>> cells;
  int begin = 0;
  for (int end : offsets) {
    cells.emplace_back(connectivity.begin() + begin, connectivity.begin() + end);
    begin = end;
  }
  return cells;
}

// Returns "" when `xml` is well formed (within what a VTK file uses: a
// prolog, elements, quoted attributes, text without '<'), else what is wrong.
inline std::string XmlWellFormedError(const std::string& xml) {
  static const std::regex kTag("<(/?)([A-Za-z_][\\w.-]*)((?:\\s+[\\w:.-]+=\"[^\"<]*\")*)\\s*(/?)>");
  std::vector<std::string> open;
  bool root_closed = false;
  size_t at = xml.rfind("<?xml", 0) == 0 ? xml.find("?>") + 2 : 0;
  auto text_between = [&](size_t from, size_t to) {
    return xml.find_first_not_of(" \t\r\n", from) < to;
  };
  for (size_t lt; (lt = xml.find('<', at)) != std::string::npos;) {
    if (open.empty() && text_between(at, lt)) return "text outside the root element";
    const size_t gt = xml.find('>', lt);
    if (gt == std::string::npos) return "unterminated tag";
    const std::string tag = xml.substr(lt, gt + 1 - lt);
    std::smatch m;
    if (!std::regex_match(tag, m, kTag)) return "malformed tag: " + tag;
    if (m[1] == "/") {
      if (open.empty() || open.back() != m[2]) return "unbalanced " + tag;
      open.pop_back();
      root_closed = open.empty();
    } else {
      if (root_closed) return "a second root element: " + tag;
      if (m[4] != "/") open.push_back(m[2]);
      root_closed = open.empty();
    }
    at = gt + 1;
  }
  if (!open.empty()) return "<" + open.back() + "> not closed";
  if (!root_closed) return "no root element";
  if (text_between(at, xml.size())) return "text after the root element";
  return "";
}

// The text inside <DataArray ... Name="name" ...>, or of the first
// DataArray after `after` when name is empty.
inline std::string DataArrayText(const std::string& xml, const std::string& name,
                                 const std::string& after = "") {
  size_t from = after.empty() ? 0 : xml.find(after);
  if (from == std::string::npos) return "";
  const size_t start =
      name.empty() ? xml.find("<DataArray", from) : xml.find("Name=\"" + name + "\"", from);
  if (start == std::string::npos) return "";
  const size_t body = xml.find('>', start) + 1;
  return xml.substr(body, xml.find("</DataArray>", body) - body);
}

inline std::string Attribute(const std::string& xml, const std::string& name) {
  const std::regex pattern(name + "=\"([^\"]*)\"");
  std::smatch m;
  return std::regex_search(xml, m, pattern) ? m[1].str() : "";
}

// Parses a .vtp that tpopt wrote; `error` says what is wrong, if anything.
inline ParsedPolyData ParseVtp(const std::string& xml, std::string* error) {
  ParsedPolyData data;
  *error = XmlWellFormedError(xml);
  if (!error->empty()) return data;
  data.points = Numbers<double>(DataArrayText(xml, "", "<Points>"));
  for (const char* tag : {"<Lines>", "<Polys>"}) {
    const size_t section = xml.find(tag);
    if (section == std::string::npos) continue;  // no cells of this kind
    const size_t section_end = xml.find(std::string("</") + (tag + 1), section);
    if (section_end == std::string::npos) {
      *error = std::string(tag) + " not closed";
      return data;
    }
    const std::string cells = xml.substr(section, section_end - section);
    auto& out = std::string(tag) == "<Lines>" ? data.lines : data.polys;
    out = CellsFromOffsets(Numbers<int>(DataArrayText(cells, "connectivity")),
                           Numbers<int>(DataArrayText(cells, "offsets")));
  }
  const size_t point_data = xml.find("<PointData");
  const std::string arrays = xml.substr(point_data, xml.find("</PointData>") - point_data);
  static const std::regex kName("Name=\"([^\"]+)\"");
  for (std::sregex_iterator it(arrays.begin(), arrays.end(), kName), end; it != end; ++it) {
    data.point_scalars[(*it)[1]] = Numbers<double>(DataArrayText(arrays, (*it)[1]));
  }
  const size_t piece_at = xml.find("<Piece");
  const std::string piece = xml.substr(piece_at, xml.find('>', piece_at) - piece_at);
  if (std::stoul(Attribute(piece, "NumberOfPoints")) != data.point_count() ||
      std::stoul(Attribute(piece, "NumberOfLines")) != data.lines.size() ||
      std::stoul(Attribute(piece, "NumberOfPolys")) != data.polys.size()) {
    *error = "Piece counts do not match the arrays";
  }
  return data;
}

// Parses a legacy ASCII POLYDATA .vtk that tpopt wrote.
inline ParsedPolyData ParseLegacyVtk(const std::string& text, std::string* error) {
  ParsedPolyData data;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  if (line.rfind("# vtk DataFile Version", 0) != 0) *error = "no legacy header";
  std::getline(in, line);  // title
  std::string word;
  in >> word;
  if (word != "ASCII") *error = "not ASCII";
  in >> word >> line;
  if (word != "DATASET" || line != "POLYDATA") *error = "not POLYDATA";
  size_t count = 0, size = 0;
  while (error->empty() && in >> word) {
    if (word == "POINTS") {
      in >> count >> line;
      data.points.resize(3 * count);
      for (double& v : data.points) in >> v;
    } else if (word == "LINES" || word == "POLYGONS") {
      in >> count >> size;
      auto& cells = word == "LINES" ? data.lines : data.polys;
      size_t read = 0;
      for (size_t c = 0; c < count; ++c) {
        int n = 0;
        in >> n;
        cells.emplace_back(n);
        for (int& index : cells.back()) in >> index;
        read += n + 1;
      }
      if (read != size) *error = word + " size " + std::to_string(size) + " != " +
                                 std::to_string(read);
    } else if (word == "POINT_DATA") {
      in >> count;
    } else if (word == "SCALARS") {
      std::string name, type, table, table_name;
      int components = 0;
      in >> name >> type >> components >> table >> table_name;
      std::vector<double>& values = data.point_scalars[name];
      values.resize(count);
      for (double& v : values) in >> v;
    } else {
      *error = "unexpected '" + word + "'";
    }
  }
  if (error->empty() && in.fail() && !in.eof()) *error = "a number did not parse";
  return data;
}

}  // namespace tpopt::testing

#endif  // TPOPT_TESTS_VTK_TEST_READER_H_
