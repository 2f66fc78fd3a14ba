#include "model/cad/cad_io.h"

#include <unistd.h>

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <GeomFill_BSplineCurves.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <IGESData_IGESWriter.hxx>
#include <IGESSelect_WorkLibrary.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <gp_Pln.hxx>
#include <limits>
#include <sstream>

#include "model/io/atomic_file.h"
#include "model/base/invalid_field.h"

namespace tpopt {
namespace {

constexpr int kDeviationGrid =
    41;  // face points per direction for ruled_deviation_mm
constexpr double kPoleTolMm = 1e-9;

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), ::tolower);
  return s;
}

std::string Extension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  return Lower(path.substr(dot + 1));
}

bool IsStep(const std::string& path) {
  const std::string ext = Extension(path);
  return ext == "stp" || ext == "step";
}

std::string Stem(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

// OCCT reports through its default messenger on stdout; tpopt's own
// messages say what went wrong, and stdout may carry a program's output.
void SilenceOcct() {
  static const bool silenced = [] {
    Message::DefaultMessenger()->RemovePrinters(
        STANDARD_TYPE(Message_PrinterOStream));
    return true;
  }();
  (void)silenced;
}

std::string FailureText(const Standard_Failure& failure) {
  const char* text = failure.GetMessageString();
  return std::string(failure.DynamicType()->Name()) +
         (text != nullptr && *text != '\0' ? std::string(" (") + text + ")"
                                           : "");
}

Status ReadText(const std::string& path, std::string* text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(path + ": cannot open");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  *text = buffer.str();
  return Status::Ok();
}

// OCCT's parsers accept a file cut short and return what they parsed; the
// end markers tell a truncated file from one that holds no surface.
Status CheckComplete(const std::string& path, const std::string& text) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    return Status::Error(path + ": the file is empty");
  }
  if (IsStep(path)) {
    if (text.find("END-ISO-10303-21") == std::string::npos) {
      return Status::Error(path +
                           ": truncated STEP file (no END-ISO-10303-21 line)");
    }
    return Status::Ok();
  }
  // IGES: the last record is the Terminate section, 'T' in column 73.
  size_t end = text.find_last_not_of(" \r\n");
  const size_t start = text.rfind('\n', end);
  const std::string last =
      text.substr(start == std::string::npos ? 0 : start + 1,
                  end - (start == std::string::npos ? 0 : start + 1) + 1);
  if (last.size() < 73 || last[72] != 'T') {
    return Status::Error(path + ": truncated IGES file (no Terminate section)");
  }
  return Status::Ok();
}

// ISO 10303-21 has no empty parameter (an omitted value is $), but OCCT
// 7.6's STEP parser takes one between two lists, ", ,(", for an entity it
// never made and crashed (README, "Hostile files"). Refuses an empty
// parameter anywhere (",,", "(," or ",)"), outside strings and comments.
Status CheckStepParameters(const std::string& path, const std::string& text) {
  int line = 1;
  char last = '\0';    // the last character outside blanks
  std::string entity;  // the instance being read, e.g. "#31"
  bool statement_start = true;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    if (c == '\'') {  // a string; '' is a quote inside it
      for (++i; i < text.size(); ++i) {
        if (text[i] == '\n') ++line;
        if (text[i] != '\'') continue;
        if (i + 1 < text.size() && text[i + 1] == '\'') {
          ++i;
        } else {
          break;
        }
      }
      last = '\'';
      statement_start = false;
      continue;
    }
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const size_t end = text.find("*/", i + 2);
      const size_t stop = end == std::string::npos ? text.size() : end + 1;
      line += static_cast<int>(
          std::count(text.begin() + i, text.begin() + stop, '\n'));
      i = stop;
      continue;
    }
    if (statement_start && c == '#') {
      size_t j = i + 1;
      while (j < text.size() &&
             std::isdigit(static_cast<unsigned char>(text[j])))
        ++j;
      entity = text.substr(i, j - i);
    }
    if ((c == ',' && (last == ',' || last == '(')) ||
        (c == ')' && last == ',')) {
      return Status::Error(path + ": line " + std::to_string(line) +
                           ": an empty parameter ('" + std::string(1, last) +
                           std::string(1, c) + "')" +
                           (entity.empty() ? "" : " in entity " + entity));
    }
    statement_start = c == ';';
    last = c;
  }
  return Status::Ok();
}

// The IGES pre-check. OCCT 7.6's IGES parser trusts the counts of a
// B-spline curve (126) or surface (128): when K or M disagree with the
// parameters present, IGESGeom_BSplineCurve/Surface::Init read arrays that
// were never filled and the process dies before tpopt gets control
// (README, "Hostile files"). So tpopt checks the layout of IGES 5.3's fixed
// ASCII form first: 80-column records, column 73 the section (S, G, D, P, T
// in that order), columns 74-80 the record's number in its section; two
// Directory Entry records an entity, whose parameter data pointer and line
// count must lie in the P section, whose P records point back at it
// (columns 66-72) and hold one record (columns 1-64) that starts with its
// type and ends with the record delimiter; and the counts of 126 and 128
// against the parameters present.
constexpr int kIgesColumns = 80;
constexpr char kIgesSections[] = "SGDPT";

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(' ');
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

// An integer field; blank is IGES's default, 0.
bool IgesInteger(const std::string& field, long long* value) {
  const std::string s = Trim(field);
  if (s.empty()) {
    *value = 0;
    return true;
  }
  char* end = nullptr;
  errno = 0;
  *value = std::strtoll(s.c_str(), &end, 10);
  return *end == '\0' && errno == 0;
}

// A real parameter (exponent E or D); blank is the default, 0.
bool IgesReal(const std::string& field) {
  std::string s = Trim(field);
  if (s.empty()) return true;
  std::replace(s.begin(), s.end(), 'D', 'E');
  std::replace(s.begin(), s.end(), 'd', 'e');
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return *end == '\0' && std::isfinite(std::strtod(s.c_str(), nullptr));
}

// Splits a record at the parameter delimiter up to the record delimiter.
// A Hollerith string (nH followed by n characters) may hold either.
bool SplitIgesRecord(const std::string& data, char param_delim,
                     char record_delim, std::vector<std::string>* params,
                     std::string* why) {
  params->clear();
  size_t i = 0;
  while (i < data.size()) {
    const size_t start = i;
    while (i < data.size() && data[i] == ' ') ++i;
    size_t digits = i;
    while (digits < data.size() &&
           std::isdigit(static_cast<unsigned char>(data[digits])))
      ++digits;
    if (digits > i && digits - i < 9 && digits < data.size() &&
        data[digits] == 'H') {
      const size_t n = std::stoul(data.substr(i, digits - i));
      if (digits + 1 + n > data.size()) {
        *why = "the string '" + data.substr(i, 20) + "' runs past the end";
        return false;
      }
      i = digits + 1 + n;
      while (i < data.size() && data[i] == ' ') ++i;
    } else {
      while (i < data.size() && data[i] != param_delim &&
             data[i] != record_delim)
        ++i;
    }
    if (i >= data.size()) break;
    params->push_back(Trim(data.substr(start, i - start)));
    if (data[i] == record_delim) return true;
    if (data[i] != param_delim) {
      *why = "'" + std::string(1, data[i]) + "' after the string '" +
             params->back() + "'";
      return false;
    }
    ++i;
  }
  *why = std::string("no record delimiter '") + record_delim + "'";
  return false;
}

// The delimiters from the Global section's first two parameters (1Hc, or
// empty for the defaults ',' and ';').
bool IgesDelimiters(const std::string& global, char* param_delim,
                    char* record_delim) {
  size_t i = global.find_first_not_of(' ');
  if (i == std::string::npos) return false;
  *param_delim = ',';
  if (global.compare(i, 2, "1H") == 0 && i + 3 < global.size()) {
    *param_delim = global[i + 2];
    i += 3;
  }
  if (global[i] != *param_delim) return false;
  i = global.find_first_not_of(' ', i + 1);
  if (i == std::string::npos) return false;
  *record_delim = ';';
  if (global.compare(i, 2, "1H") == 0 && i + 3 < global.size()) {
    *record_delim = global[i + 2];
    i += 3;
  }
  return *record_delim != *param_delim &&
         (global[i] == *param_delim || global[i] == *record_delim);
}

// The counts of a rational B-spline curve (126) or surface (128) against
// its parameters (params[0] is the type). Curve: K, M, PROP1-4, K + M + 2
// knots, K + 1 weights, 3 (K + 1) coordinates, V(0), V(1) (the unit normal
// that may follow is optional). Surface: K1, K2, M1, M2, PROP1-5, K1 + M1 +
// 2 and K2 + M2 + 2 knots, (K1 + 1)(K2 + 1) weights, three times as many
// coordinates, U(0), U(1), V(0), V(1). The degree M >= 1 and K >= M.
Status CheckIgesBSpline(const std::string& name, bool surface,
                        const std::vector<std::string>& params) {
  const std::vector<std::string> labels =
      surface
          ? std::vector<std::string>{"K1",    "K2",    "M1",    "M2",   "PROP1",
                                     "PROP2", "PROP3", "PROP4", "PROP5"}
          : std::vector<std::string>{"K",     "M",     "PROP1",
                                     "PROP2", "PROP3", "PROP4"};
  const long long present = static_cast<long long>(params.size());
  std::vector<long long> n(labels.size());
  for (size_t i = 0; i < labels.size(); ++i) {
    if (i + 1 >= params.size()) {
      return Status::Error(name + ": its parameter data end after " +
                           std::to_string(present - 1) +
                           " parameters, before " + labels[i]);
    }
    if (!IgesInteger(params[i + 1], &n[i])) {
      return Status::Error(name + ": " + labels[i] + " '" + params[i + 1] +
                           "' is not an integer");
    }
  }
  const int pairs = surface ? 2 : 1;
  std::ostringstream counts;
  for (int d = 0; d < pairs; ++d) {
    const long long k = n[d], m = n[d + pairs];
    counts << (d > 0 ? ", " : "") << labels[d] << " = " << k << ", "
           << labels[d + pairs] << " = " << m;
    if (m < 1 || k < m) {
      return Status::Error(name + ": " + counts.str() +
                           ": the degree must be at least 1 and K at least M");
    }
    if (k >= present) {
      return Status::Error(name + ": " + counts.str() + " ask for more than " +
                           "the " + std::to_string(present - 1) +
                           " parameters its parameter data hold");
    }
  }
  long long need = 1 + static_cast<long long>(labels.size());
  if (surface) {
    need +=
        (n[0] + n[2] + 2) + (n[1] + n[3] + 2) + 4 * (n[0] + 1) * (n[1] + 1) + 4;
  } else {
    need += (n[0] + n[1] + 2) + 4 * (n[0] + 1) + 2;
  }
  if (present < need) {
    return Status::Error(
        name + ": " + counts.str() + " need " + std::to_string(need - 1) +
        " parameters, its parameter data hold " + std::to_string(present - 1));
  }
  for (long long i = static_cast<long long>(labels.size()) + 1; i < need; ++i) {
    if (!IgesReal(params[i])) {
      return Status::Error(name + ": parameter " + std::to_string(i) + " '" +
                           params[i] + "' is not a number");
    }
  }
  return Status::Ok();
}

Status CheckIgesLayout(const std::string& path, const std::string& text) {
  std::vector<std::string> sections[5];
  std::vector<int> first_line(5, 0);  // file line of each section's start
  int stage = 0, line_number = 0;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos &&
        in.peek() == std::char_traits<char>::eof())
      break;  // a blank last line
    const std::string where = path + ": line " + std::to_string(line_number);
    if (line.size() != kIgesColumns) {
      return Status::Error(where + ": a record of " +
                           std::to_string(line.size()) + " columns, not " +
                           std::to_string(kIgesColumns) +
                           " (IGES fixed ASCII form)");
    }
    const char letter = line[72];
    const char* found = std::strchr(kIgesSections, letter);
    if (letter == '\0' || found == nullptr) {
      return Status::Error(where + ": column 73 is '" + std::string(1, letter) +
                           "', not S, G, D, P or T (a section letter)");
    }
    const int k = static_cast<int>(found - kIgesSections);
    if (k < stage) {
      return Status::Error(where + ": a " + std::string(1, letter) +
                           " record after the " +
                           std::string(1, kIgesSections[stage]) + " section");
    }
    stage = k;
    long long sequence = 0;
    const long long expected = static_cast<long long>(sections[k].size()) + 1;
    if (!IgesInteger(line.substr(73), &sequence) || sequence != expected) {
      return Status::Error(where + ": sequence number '" + line.substr(73) +
                           "', expected " + std::to_string(expected) +
                           " in the " + std::string(1, letter) + " section");
    }
    if (sections[k].empty()) first_line[k] = line_number;
    sections[k].push_back(line);
  }
  const std::vector<std::string>& global = sections[1];
  const std::vector<std::string>& directory = sections[2];
  const std::vector<std::string>& parameters = sections[3];
  if (sections[4].size() != 1) {
    return Status::Error(path + ": " + std::to_string(sections[4].size()) +
                         " Terminate records, not 1");
  }
  for (int k = 0; k < 4; ++k) {
    const std::string field = sections[4][0].substr(8 * k, 8);
    long long count = -1;
    if (field[0] != kIgesSections[k] || !IgesInteger(field.substr(1), &count) ||
        count != static_cast<long long>(sections[k].size())) {
      return Status::Error(path + ": the Terminate record's field '" + field +
                           "' does not count the " +
                           std::to_string(sections[k].size()) + " " +
                           std::string(1, kIgesSections[k]) + " records");
    }
  }
  if (global.empty()) return Status::Error(path + ": no Global section");
  if (directory.size() % 2 != 0) {
    return Status::Error(path + ": the Directory Entry section has " +
                         std::to_string(directory.size()) +
                         " records, not two an entity");
  }
  std::string global_text;
  for (const std::string& g : global) global_text += g.substr(0, 72);
  char param_delim = ',', record_delim = ';';
  std::vector<std::string> params;
  std::string why;
  if (!IgesDelimiters(global_text, &param_delim, &record_delim) ||
      !SplitIgesRecord(global_text, param_delim, record_delim, &params, &why)) {
    return Status::Error(path + ": line " + std::to_string(first_line[1]) +
                         ": the Global section is not a record" +
                         (why.empty() ? "" : ": " + why));
  }
  for (size_t e = 0; e < directory.size(); e += 2) {
    const std::string& a = directory[e];
    const std::string& b = directory[e + 1];
    const int de = static_cast<int>(e) + 1;
    long long type = 0, type2 = 0, pointer = 0, count = 0;
    const std::string where = path + ": directory entry " + std::to_string(de) +
                              " (line " + std::to_string(first_line[2] + e) +
                              ")";
    if (!IgesInteger(a.substr(0, 8), &type) ||
        !IgesInteger(b.substr(0, 8), &type2) || type != type2) {
      return Status::Error(where + ": entity type '" + Trim(a.substr(0, 8)) +
                           "' and '" + Trim(b.substr(0, 8)) + "' disagree");
    }
    const std::string name = path + ": entity DE " + std::to_string(de) +
                             " (type " + std::to_string(type) + ")";
    if (!IgesInteger(a.substr(8, 8), &pointer) ||
        !IgesInteger(b.substr(24, 8), &count)) {
      return Status::Error(name + ": parameter data pointer '" +
                           Trim(a.substr(8, 8)) + "' or line count '" +
                           Trim(b.substr(24, 8)) + "' is not a number");
    }
    const long long nbp = static_cast<long long>(parameters.size());
    if (pointer < 1 || count < 1 || pointer > nbp ||
        count > nbp - pointer + 1) {
      return Status::Error(
          name + ": its parameter data, " + std::to_string(count) +
          " lines from P line " + std::to_string(pointer) +
          ", do not lie in the P section (" + std::to_string(nbp) + " lines)");
    }
    std::string data;
    for (long long p = pointer; p < pointer + count; ++p) {
      const std::string& record = parameters[p - 1];
      long long back = 0;
      if (!IgesInteger(record.substr(64, 8), &back) || back != de) {
        return Status::Error(name + ": P line " + std::to_string(p) +
                             " (line " + std::to_string(first_line[3] + p - 1) +
                             ") points back to directory entry '" +
                             Trim(record.substr(64, 8)) + "'");
      }
      data += record.substr(0, 64);
    }
    if (!SplitIgesRecord(data, param_delim, record_delim, &params, &why)) {
      return Status::Error(name + ": its parameter data (P lines " +
                           std::to_string(pointer) + " to " +
                           std::to_string(pointer + count - 1) + "): " + why);
    }
    long long first = 0;
    if (params.empty() || !IgesInteger(params[0], &first) || first != type) {
      return Status::Error(name + ": its parameter data start with '" +
                           (params.empty() ? "" : params[0]) +
                           "', not its type");
    }
    if (type == 126 || type == 128) {
      RETURN_IF_ERROR(CheckIgesBSpline(name, type == 128, params));
    }
  }
  return Status::Ok();
}

// Fails naming the first entity the parser flagged: OCCT 7.6 goes on to
// transfer such a model, and a B-spline whose control point refers to a
// missing or wrong entity crashes its STEP translator (README).
Status CheckParsed(const std::string& path, XSControl_Reader& reader) {
  const Interface_CheckIterator checks = reader.WS()->ModelCheckList();
  if (checks.IsEmpty(true)) return Status::Ok();
  const Handle(Interface_InterfaceModel) model = reader.WS()->Model();
  for (checks.Start(); checks.More(); checks.Next()) {
    const Handle(Interface_Check)& check = checks.Value();
    if (!check->HasFailed()) continue;
    std::string where;
    const int number = checks.Number();
    if (number > 0 && !model.IsNull() && number <= model->NbEntities()) {
      where =
          "entity " +
          std::string(model->StringLabel(model->Value(number))->ToCString()) +
          ": ";
    }
    return Status::Error(path + ": " + where + check->CFail(1));
  }
  return Status::Error(path + ": the parser reported errors");
}

// Parses the file, checks the parse and translates every root.
Status ReadAndTransfer(const std::string& path, const std::string& format,
                       XSControl_Reader* reader, TopoDS_Shape* shape) {
  if (reader->ReadFile(path.c_str()) != IFSelect_RetDone) {
    return Status::Error(path + ": not a readable " + format + " file");
  }
  RETURN_IF_ERROR(CheckParsed(path, *reader));
  reader->TransferRoots();
  *shape = reader->OneShape();
  return Status::Ok();
}

struct LoadedFile {
  std::vector<TopoDS_Face> faces;
  std::string length_unit;
};

Status LoadFaces(const std::string& path, LoadedFile* loaded) {
  if (!IsCadSurfacePath(path)) {
    return Status::Error(
        path + ": not a STEP (.stp, .step) or IGES (.igs, .iges) file");
  }
  std::string text;
  Status s = ReadText(path, &text);
  if (s.ok()) s = CheckComplete(path, text);
  if (s.ok()) {
    s = IsStep(path) ? CheckStepParameters(path, text)
                     : CheckIgesLayout(path, text);
  }
  if (!s.ok()) return s;
  SilenceOcct();
  TopoDS_Shape shape;
  if (IsStep(path)) {
    STEPControl_Reader reader;
    RETURN_IF_ERROR(ReadAndTransfer(path, "STEP", &reader, &shape));
    TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
    reader.FileUnits(lengths, angles, solid_angles);
    if (!lengths.IsEmpty()) loaded->length_unit = lengths.First().ToCString();
  } else {
    IGESControl_Reader reader;
    RETURN_IF_ERROR(ReadAndTransfer(path, "IGES", &reader, &shape));
    const Handle(TCollection_HAsciiString) unit =
        reader.IGESModel()->GlobalSection().UnitName();
    if (!unit.IsNull()) loaded->length_unit = unit->ToCString();
  }
  if (!shape.IsNull()) {
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
      loaded->faces.push_back(TopoDS::Face(e.Current()));
    }
  }
  if (loaded->faces.empty())
    return Status::Error(path + ": the file holds no surface (no face)");
  return Status::Ok();
}

// The face's surface without rectangular trims, and whether the face is
// trimmed (its parameter bounds inside the surface's, or inner wires).
Handle(Geom_Surface) NaturalSurface(const TopoDS_Face& face, bool* trimmed) {
  Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  *trimmed = false;
  if (surface.IsNull()) return surface;
  while (true) {
    Handle(Geom_RectangularTrimmedSurface) t =
        Handle(Geom_RectangularTrimmedSurface)::DownCast(surface);
    if (t.IsNull()) break;
    surface = t->BasisSurface();
  }
  double u0, u1, v0, v1, fu0, fu1, fv0, fv1;
  surface->Bounds(u0, u1, v0, v1);
  BRepTools::UVBounds(face, fu0, fu1, fv0, fv1);
  const double tol_u = 1e-9 * std::max(1.0, std::abs(u1 - u0));
  const double tol_v = 1e-9 * std::max(1.0, std::abs(v1 - v0));
  const bool finite = std::isfinite(u0) && std::isfinite(u1) &&
                      std::isfinite(v0) && std::isfinite(v1);
  if (finite && (fu0 > u0 + tol_u || fu1 < u1 - tol_u || fv0 > v0 + tol_v ||
                 fv1 < v1 - tol_v)) {
    *trimmed = true;
  }
  int wires = 0;
  for (TopExp_Explorer e(face, TopAbs_WIRE); e.More(); e.Next()) ++wires;
  if (wires > 1) *trimmed = true;
  return surface;
}

CadFaceSummary Summarize(int index, const Handle(Geom_Surface) & surface) {
  CadFaceSummary summary;
  summary.index = index;
  summary.surface_type =
      surface.IsNull() ? "no surface" : surface->DynamicType()->Name();
  Handle(Geom_BSplineSurface) bs =
      Handle(Geom_BSplineSurface)::DownCast(surface);
  Handle(Geom_BezierSurface) bz = Handle(Geom_BezierSurface)::DownCast(surface);
  if (!bs.IsNull()) {
    summary.degree_u = bs->UDegree();
    summary.degree_v = bs->VDegree();
    summary.poles_u = bs->NbUPoles();
    summary.poles_v = bs->NbVPoles();
    summary.rational = bs->IsURational() || bs->IsVRational();
  } else if (!bz.IsNull()) {
    summary.degree_u = bz->UDegree();
    summary.degree_v = bz->VDegree();
    summary.poles_u = bz->NbUPoles();
    summary.poles_v = bz->NbVPoles();
    summary.rational = bz->IsURational() || bz->IsVRational();
  }
  return summary;
}

std::string Listing(const std::vector<CadFaceSummary>& faces) {
  std::string out;
  for (const CadFaceSummary& f : faces) out += "\n  " + f.Describe();
  return out;
}

// The chosen face, with its natural surface as a clamped B-spline.
struct ChosenFace {
  std::string what;  // "file: face N", the start of its messages
  CadFaceSummary summary;
  Handle(Geom_BSplineSurface) bspline;
  bool trimmed = false;
  bool reversed = false;
};

Status ChooseFace(const std::string& path, const LoadedFile& loaded,
                  int face_index, ChosenFace* chosen) {
  std::vector<CadFaceSummary> summaries;
  std::vector<Handle(Geom_Surface)> surfaces;
  std::vector<bool> trims;
  for (size_t i = 0; i < loaded.faces.size(); ++i) {
    bool trimmed = false;
    surfaces.push_back(NaturalSurface(loaded.faces[i], &trimmed));
    trims.push_back(trimmed);
    summaries.push_back(Summarize(static_cast<int>(i), surfaces.back()));
  }
  const int n = static_cast<int>(summaries.size());
  if (face_index < 0 && n > 1) {
    return Status::Error(
        path + ": the file holds " + std::to_string(n) +
        " faces; choose one with --face=N:" + Listing(summaries));
  }
  const int index = face_index < 0 ? 0 : face_index;
  if (index >= n) {
    return Status::Error(path + ": face " + std::to_string(face_index) +
                         " does not exist; the file holds " +
                         std::to_string(n) + (n == 1 ? " face:" : " faces:") +
                         Listing(summaries));
  }
  const std::string what = path + ": face " + std::to_string(index);
  chosen->what = what;
  chosen->summary = summaries[index];
  chosen->trimmed = trims[index];
  chosen->reversed = loaded.faces[index].Orientation() == TopAbs_REVERSED;
  const Handle(Geom_Surface)& surface = surfaces[index];
  Handle(Geom_BSplineSurface) bs =
      Handle(Geom_BSplineSurface)::DownCast(surface);
  Handle(Geom_BezierSurface) bz = Handle(Geom_BezierSurface)::DownCast(surface);
  Handle(Geom_SurfaceOfLinearExtrusion) extrusion =
      Handle(Geom_SurfaceOfLinearExtrusion)::DownCast(surface);
  if (!extrusion.IsNull()) {
    // Unbounded along its direction: the face's extent there, the curve's
    // natural range along it; an exact B-spline (rational when the curve is).
    double u0, u1, v0, v1, fu0, fu1, fv0, fv1;
    extrusion->Bounds(u0, u1, v0, v1);
    BRepTools::UVBounds(loaded.faces[index], fu0, fu1, fv0, fv1);
    bs = GeomConvert::SurfaceToBSplineSurface(
        new Geom_RectangularTrimmedSurface(extrusion, u0, u1, fv0, fv1));
    const CadFaceSummary converted = Summarize(index, bs);
    chosen->summary.degree_u = converted.degree_u;
    chosen->summary.degree_v = converted.degree_v;
    chosen->summary.poles_u = converted.poles_u;
    chosen->summary.poles_v = converted.poles_v;
    chosen->summary.rational = converted.rational;
  } else if (!bz.IsNull()) {
    bs = GeomConvert::SurfaceToBSplineSurface(bz);
  } else if (!bs.IsNull()) {
    bs = Handle(Geom_BSplineSurface)::DownCast(bs->Copy());
  } else {
    return Status::Error(
        what + " is a " + chosen->summary.surface_type +
        ", not a B-spline, Bezier or linear extrusion surface");
  }
  if (chosen->summary.rational) {
    double w_min = std::numeric_limits<double>::infinity(), w_max = -w_min;
    for (int i = 1; i <= bs->NbUPoles(); ++i) {
      for (int j = 1; j <= bs->NbVPoles(); ++j) {
        w_min = std::min(w_min, bs->Weight(i, j));
        w_max = std::max(w_max, bs->Weight(i, j));
      }
    }
    std::ostringstream err;
    err << what << ": a rational " << chosen->summary.surface_type
        << " (weights " << w_min << " to " << w_max
        << "); tpopt takes non-rational B-spline surfaces only";
    return Status::Error(err.str());
  }
  if (bs->IsUPeriodic()) bs->SetUNotPeriodic();
  if (bs->IsVPeriodic()) bs->SetVNotPeriodic();
  chosen->bspline = bs;
  return Status::Ok();
}

// Runs `body`, turning an OCCT exception into an error naming the file:
// the library throws none.
Status GuardOcct(const std::string& path, const std::function<Status()>& body) {
  try {
    return body();
  } catch (const Standard_Failure& failure) {
    return Status::Error(path +
                         ": OpenCASCADE failed: " + FailureText(failure));
  }
}

// Validates the options, reads the file and picks the face.
Status LoadChosenFace(const std::string& path, const CadReadOptions& options,
                      LoadedFile* loaded, ChosenFace* face) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(path + ": " + why);
  Status s = LoadFaces(path, loaded);
  if (s.ok()) s = ChooseFace(path, *loaded, options.face_index, face);
  return s;
}

// Under GuardOcct, reads the file and its chosen face and runs `body` on
// them (the reads of ReadCadRuledSurface and ReadCadBSplineSurface).
Status ReadChosenFace(
    const std::string& path, const CadReadOptions& options,
    const std::function<Status(const LoadedFile&, const ChosenFace&)>& body) {
  return GuardOcct(path, [&]() {
    LoadedFile loaded;
    ChosenFace face;
    const Status s = LoadChosenFace(path, options, &loaded, &face);
    return s.ok() ? body(loaded, face) : s;
  });
}

std::vector<double> FlatKnots(const Handle(Geom_BSplineSurface) & bs,
                              bool along_u) {
  const int n = along_u ? bs->NbUPoles() + bs->UDegree() + 1
                        : bs->NbVPoles() + bs->VDegree() + 1;
  TColStd_Array1OfReal knots(1, n);
  if (along_u) {
    bs->UKnotSequence(knots);
  } else {
    bs->VKnotSequence(knots);
  }
  return std::vector<double>(knots.begin(), knots.end());
}

Eigen::Vector3d ToEigen(const gp_Pnt& p) {
  return Eigen::Vector3d(p.X(), p.Y(), p.Z());
}

// The face's poles as net[a][b], a along the rails, b along the ruling.
std::vector<std::vector<Eigen::Vector3d>> Net(
    const Handle(Geom_BSplineSurface) & bs, bool ruling_u) {
  const int na = ruling_u ? bs->NbVPoles() : bs->NbUPoles();
  const int nb = ruling_u ? bs->NbUPoles() : bs->NbVPoles();
  std::vector<std::vector<Eigen::Vector3d>> net(
      na, std::vector<Eigen::Vector3d>(nb));
  for (int a = 0; a < na; ++a) {
    for (int b = 0; b < nb; ++b) {
      net[a][b] =
          ToEigen(ruling_u ? bs->Pole(b + 1, a + 1) : bs->Pole(a + 1, b + 1));
    }
  }
  return net;
}

Status RailsOf(const Handle(Geom_BSplineSurface) & bs, bool ruling_u,
               const std::string& what, const std::string& name,
               CutterSide side, RuledSurface* surface) {
  const auto net = Net(bs, ruling_u);
  std::vector<Eigen::Vector3d> first, last;
  for (const auto& row : net) {
    first.push_back(row.front());
    last.push_back(row.back());
  }
  const int degree = ruling_u ? bs->VDegree() : bs->UDegree();
  const std::vector<double> knots = FlatKnots(bs, !ruling_u);
  BSplineCurve rail0, rail1;
  Status s =
      BSplineCurve::Create(degree, knots, first, what + ": rail 0", &rail0);
  if (s.ok())
    s = BSplineCurve::Create(degree, knots, last, what + ": rail 1", &rail1);
  if (s.ok()) *surface = RuledSurface(name, rail0, rail1, side);
  return s;
}

bool ExactlyRuled(const Handle(Geom_BSplineSurface) & bs, bool ruling_u) {
  return ruling_u ? bs->UDegree() == 1 && bs->NbUPoles() == 2
                  : bs->VDegree() == 1 && bs->NbVPoles() == 2;
}

// The face point at normalised rail parameter s and ruling parameter t.
gp_Pnt FacePoint(const Handle(Geom_BSplineSurface) & bs, bool ruling_u,
                 double s, double t) {
  double u0, u1, v0, v1;
  bs->Bounds(u0, u1, v0, v1);
  const double a = ruling_u ? t : s, b = ruling_u ? s : t;
  return bs->Value(u0 + a * (u1 - u0), v0 + b * (v1 - v0));
}

// Distance from p to the ruled surface: Gauss-Newton on (u, v) from the
// point of equal parameters, the smaller of the two distances kept.
double DistanceToRuled(const RuledSurface& ruled, const Eigen::Vector3d& p,
                       double u, double v) {
  double best = (ruled.Point(u, v) - p).norm();
  for (int iter = 0; iter < 30; ++iter) {
    const Eigen::Vector3d r = ruled.Point(u, v) - p;
    Eigen::Matrix<double, 3, 2> j;
    j.col(0) = ruled.Du(u, v);
    j.col(1) = ruled.Dv(u);
    const Eigen::Matrix2d jtj = j.transpose() * j;
    if (std::abs(jtj.determinant()) < 1e-300) break;
    const Eigen::Vector2d step = -jtj.ldlt().solve(j.transpose() * r);
    u = std::clamp(u + step.x(), 0.0, 1.0);
    v = std::clamp(v + step.y(), 0.0, 1.0);
    best = std::min(best, (ruled.Point(u, v) - p).norm());
    if (step.norm() < 1e-14) break;
  }
  return best;
}

double RuledDeviationMm(const Handle(Geom_BSplineSurface) & bs, bool ruling_u,
                        const RuledSurface& ruled) {
  double worst = 0.0;
  for (int i = 0; i < kDeviationGrid; ++i) {
    for (int j = 0; j < kDeviationGrid; ++j) {
      const double s = i / (kDeviationGrid - 1.0),
                   t = j / (kDeviationGrid - 1.0);
      worst = std::max(
          worst,
          DistanceToRuled(ruled, ToEigen(FacePoint(bs, ruling_u, s, t)), s, t));
    }
  }
  return worst;
}

// Outward normal S_u x S_v of a FORWARD face; the cutter lies on it.
double OutwardSign(const ChosenFace& face, bool flip) {
  return (face.reversed ? -1.0 : 1.0) * (flip ? -1.0 : 1.0);
}

void FillInfo(const std::string& path, const LoadedFile& loaded,
              const ChosenFace& face, CadSurfaceInfo* info) {
  info->file = path;
  info->length_unit = loaded.length_unit;
  info->face_count = static_cast<int>(loaded.faces.size());
  info->face = face.summary;
  info->trimmed = face.trimmed;
  info->face_reversed = face.reversed;
}

std::vector<std::pair<double, int>> KnotsAndMults(
    const std::vector<double>& flat) {
  std::vector<std::pair<double, int>> out;
  for (double k : flat) {
    if (!out.empty() && k == out.back().first) {
      ++out.back().second;
    } else {
      out.push_back({k, 1});
    }
  }
  return out;
}

void ToOcctKnots(const std::vector<double>& flat, TColStd_Array1OfReal* knots,
                 TColStd_Array1OfInteger* mults) {
  const auto km = KnotsAndMults(flat);
  knots->Resize(1, static_cast<int>(km.size()), false);
  mults->Resize(1, static_cast<int>(km.size()), false);
  for (size_t i = 0; i < km.size(); ++i) {
    knots->SetValue(static_cast<int>(i) + 1, km[i].first);
    mults->SetValue(static_cast<int>(i) + 1, km[i].second);
  }
}

gp_Pnt ToGp(const Eigen::Vector3d& p) { return gp_Pnt(p.x(), p.y(), p.z()); }

Status PatchFace(const CadPatch& patch, int index, TopoDS_Face* face) {
  const std::string what = "patch " + std::to_string(index);
  const int nu = static_cast<int>(patch.poles.size());
  const int nv = nu == 0 ? 0 : static_cast<int>(patch.poles[0].size());
  if (nu < 2 || nv < 2)
    return Status::Error(what + ": needs at least 2 x 2 poles");
  for (const auto& row : patch.poles) {
    if (static_cast<int>(row.size()) != nv)
      return Status::Error(what + ": rows differ in length");
  }
  const bool rational = !patch.weights.empty();
  if (rational && (static_cast<int>(patch.weights.size()) != nu ||
                   static_cast<int>(patch.weights[0].size()) != nv)) {
    return Status::Error(what + ": weights are not " + std::to_string(nu) +
                         " x " + std::to_string(nv));
  }
  Handle(Geom_Surface) surface;
  if (patch.as_plane) {
    const gp_Pnt origin = ToGp(patch.poles[0][0]);
    const Eigen::Vector3d du = patch.poles.back()[0] - patch.poles[0][0];
    const Eigen::Vector3d dv = patch.poles[0].back() - patch.poles[0][0];
    const Eigen::Vector3d n = du.cross(dv);
    gp_Pln plane(gp_Ax3(origin, gp_Dir(n.x(), n.y(), n.z()),
                        gp_Dir(du.x(), du.y(), du.z())));
    BRepBuilderAPI_MakeFace make(plane, 0.0, du.norm(), 0.0, dv.norm());
    if (!make.IsDone())
      return Status::Error(what + ": OCCT could not make the plane face");
    *face = make.Face();
    if (patch.reversed) face->Reverse();
    return Status::Ok();
  }
  if (patch.extrusion_mm.norm() > 0.0) {
    const int n = nu;
    TColgp_Array1OfPnt curve_poles(1, n);
    for (int i = 0; i < n; ++i)
      curve_poles.SetValue(i + 1, ToGp(patch.poles[i][0]));
    TColStd_Array1OfReal knots(1, 1);
    TColStd_Array1OfInteger mults(1, 1);
    ToOcctKnots(patch.knots_u, &knots, &mults);
    Handle(Geom_BSplineCurve) curve =
        new Geom_BSplineCurve(curve_poles, knots, mults, patch.degree_u);
    const Eigen::Vector3d& d = patch.extrusion_mm;
    surface =
        new Geom_SurfaceOfLinearExtrusion(curve, gp_Dir(d.x(), d.y(), d.z()));
    BRepBuilderAPI_MakeFace make(surface, curve->FirstParameter(),
                                 curve->LastParameter(), 0.0, d.norm(), 1e-7);
    if (!make.IsDone())
      return Status::Error(what + ": OCCT could not make a face");
    *face = make.Face();
    if (patch.reversed) face->Reverse();
    return Status::Ok();
  }
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      poles.SetValue(i + 1, j + 1, ToGp(patch.poles[i][j]));
      weights.SetValue(i + 1, j + 1, rational ? patch.weights[i][j] : 1.0);
    }
  }
  if (patch.bezier) {
    surface = rational ? new Geom_BezierSurface(poles, weights)
                       : new Geom_BezierSurface(poles);
  } else {
    if (static_cast<int>(patch.knots_u.size()) != nu + patch.degree_u + 1 ||
        static_cast<int>(patch.knots_v.size()) != nv + patch.degree_v + 1) {
      return Status::Error(what +
                           ": knot counts do not match poles and degrees");
    }
    TColStd_Array1OfReal ku(1, 1), kv(1, 1);
    TColStd_Array1OfInteger mu(1, 1), mv(1, 1);
    ToOcctKnots(patch.knots_u, &ku, &mu);
    ToOcctKnots(patch.knots_v, &kv, &mv);
    if (rational) {
      surface = new Geom_BSplineSurface(poles, weights, ku, kv, mu, mv,
                                        patch.degree_u, patch.degree_v);
    } else {
      surface = new Geom_BSplineSurface(poles, ku, kv, mu, mv, patch.degree_u,
                                        patch.degree_v);
    }
  }
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  BRepBuilderAPI_MakeFace make(surface, u0, u0 + patch.trim_u * (u1 - u0), v0,
                               v1, 1e-7);
  if (!make.IsDone())
    return Status::Error(what + ": OCCT could not make a face");
  *face = make.Face();
  if (patch.reversed) face->Reverse();
  return Status::Ok();
}

// Writes the shape to a scratch file with OCCT, then to `path` atomically.
Status WriteShape(const std::string& path, const TopoDS_Shape& shape,
                  const CadWriteOptions& options) {
  std::string scratch = "/tmp/tpopt_cad_XXXXXX";
  const int fd = mkstemp(scratch.data());
  if (fd < 0)
    return Status::Error(path + ": cannot make a scratch file in /tmp");
  close(fd);
  const std::string file = scratch + (IsStep(path) ? ".stp" : ".igs");
  std::remove(scratch.c_str());
  bool written = false;
  if (IsStep(path)) {
    STEPControl_Writer writer;
    Interface_Static::SetCVal("write.step.unit", options.length_unit.c_str());
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    writer.Model()->SetWriteLengthUnit(options.length_unit == "INCH" ? 25.4
                                                                     : 1.0);
    if (writer.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone) {
      APIHeaderSection_MakeHeader header(writer.Model());
      header.SetTimeStamp(
          new TCollection_HAsciiString(options.time_stamp.c_str()));
      header.SetOriginatingSystem(
          new TCollection_HAsciiString("tpopt (OpenCASCADE)"));
      header.SetAuthorValue(1, new TCollection_HAsciiString("tpopt"));
      written = writer.Write(file.c_str()) == IFSelect_RetDone;
    }
    Interface_Static::SetCVal("write.step.unit", "MM");
  } else {
    IGESControl_Controller::Init();
    IGESControl_Writer writer(options.length_unit.c_str(), 0);
    if (writer.AddShape(shape)) {
      writer.ComputeModel();
      // IGESControl_Writer::Write keeps 9 digits (1e-7 mm at 100 mm);
      // 15 keep a face to 1e-13 mm.
      IGESData_IGESWriter iges(writer.Model());
      iges.FloatWriter().SetFormat("%.15E");
      iges.SendModel(IGESSelect_WorkLibrary::DefineProtocol());
      std::ofstream out(file, std::ios::binary);
      written = iges.Print(out) && out.good();
    }
  }
  std::string text;
  Status s = written ? ReadText(file, &text)
                     : Status::Error(path + ": OCCT could not write");
  std::remove(file.c_str());
  if (s.ok()) s = WriteFileAtomically(path, text);
  return s;
}

}  // namespace

bool IsCadSurfacePath(const std::string& path) {
  const std::string ext = Extension(path);
  return ext == "stp" || ext == "step" || ext == "igs" || ext == "iges";
}

bool CadIoAvailable() { return true; }

bool CadReadOptions::IsValid(std::string* why) const {
  if (face_index < -1) {
    *why = InvalidField("--face", face_index, ">= 0 (or -1: the only face)");
    return false;
  }
  if (!ruling.empty() && ruling != "u" && ruling != "v") {
    *why = InvalidField("--ruling", ruling, "u or v");
    return false;
  }
  if (!(max_ruled_deviation_mm >= 0.0) ||
      !std::isfinite(max_ruled_deviation_mm)) {
    *why = InvalidField("--max_ruled_deviation_mm", max_ruled_deviation_mm,
                        "finite and >= 0");
    return false;
  }
  return true;
}

bool CadWriteOptions::IsValid(std::string* why) const {
  if (length_unit != "MM" && length_unit != "INCH") {
    *why = InvalidField("length_unit", length_unit, "MM or INCH");
    return false;
  }
  return true;
}

std::string CadFaceSummary::Describe() const {
  std::string out = "face " + std::to_string(index) + ": " + surface_type;
  if (degree_u > 0) {
    out += ", degree " + std::to_string(degree_u) + " x " +
           std::to_string(degree_v) + ", " + std::to_string(poles_u) + " x " +
           std::to_string(poles_v) + " poles";
    if (rational) out += ", rational";
  }
  return out;
}

Status ListCadFaces(const std::string& path,
                    std::vector<CadFaceSummary>* faces) {
  return GuardOcct(path, [&]() {
    LoadedFile loaded;
    RETURN_IF_ERROR(LoadFaces(path, &loaded));
    faces->clear();
    for (size_t i = 0; i < loaded.faces.size(); ++i) {
      bool trimmed = false;
      faces->push_back(Summarize(static_cast<int>(i),
                                 NaturalSurface(loaded.faces[i], &trimmed)));
    }
    return Status::Ok();
  });
}

Status ReadCadRuledSurface(const std::string& path,
                           const CadReadOptions& options, RuledSurface* surface,
                           CadSurfaceInfo* info) {
  return ReadChosenFace(
      path, options, [&](const LoadedFile& loaded, const ChosenFace& face) {
        const std::string& what = face.what;
        const Handle(Geom_BSplineSurface)& bs = face.bspline;
        const std::string name =
            Stem(path) + " face " + std::to_string(face.summary.index);
        // The candidate rulings: the one asked for, else the exactly ruled
        // direction (v first: a bilinear patch is ruled both ways), else both.
        std::vector<bool> candidates;
        if (!options.ruling.empty()) {
          candidates = {options.ruling == "u"};
        } else if (ExactlyRuled(bs, false)) {
          candidates = {false};
        } else if (ExactlyRuled(bs, true)) {
          candidates = {true};
        } else {
          candidates = {false, true};
        }
        double best = std::numeric_limits<double>::infinity();
        for (bool ruling_u : candidates) {
          // N = r_u x r_v is S_u x S_v when the ruling is v, its opposite when
          // u.
          const double sign = OutwardSign(face, options.flip_cutter_side) *
                              (ruling_u ? -1.0 : 1.0);
          RuledSurface ruled;
          RETURN_IF_ERROR(RailsOf(bs, ruling_u, what, name,
                                  sign > 0 ? CutterSide::kPositive : CutterSide::kNegative,
                                  &ruled));
          const bool exact = ExactlyRuled(bs, ruling_u);
          const double deviation =
              exact ? 0.0 : RuledDeviationMm(bs, ruling_u, ruled);
          if (deviation < best) {
            best = deviation;
            *surface = ruled;
            info->ruling = ruling_u ? "u" : "v";
            info->exact_ruled = exact;
            info->ruled_deviation_mm = deviation;
          }
        }
        FillInfo(path, loaded, face, info);
        if (best > options.max_ruled_deviation_mm) {
          std::ostringstream err;
          err << what << " is not ruled: it lies up to " << best
              << " mm from the ruled surface between its boundary curves "
                 "across "
                 "the ruling "
              << info->ruling << ", above --max_ruled_deviation_mm="
              << options.max_ruled_deviation_mm;
          return Status::Error(err.str());
        }
        return Status::Ok();
      });
}

Status ReadCadBSplineSurface(const std::string& path,
                             const CadReadOptions& options,
                             BSplineSurface* surface, double* cutter_side_sign,
                             CadSurfaceInfo* info) {
  return ReadChosenFace(
      path, options, [&](const LoadedFile& loaded, const ChosenFace& face) {
        const std::string& what = face.what;
        const Handle(Geom_BSplineSurface)& bs = face.bspline;
        if (bs->UDegree() > BSplineSurface::kMaxDegree ||
            bs->VDegree() > BSplineSurface::kMaxDegree) {
          return Status::Error(what + ": degree " +
                               std::to_string(bs->UDegree()) + " x " +
                               std::to_string(bs->VDegree()) + " is above " +
                               std::to_string(BSplineSurface::kMaxDegree));
        }
        RETURN_IF_ERROR(BSplineSurface::Create(bs->UDegree(), bs->VDegree(), FlatKnots(bs, true),
                                               FlatKnots(bs, false), Net(bs, false), what,
                                               surface));
        *cutter_side_sign = OutwardSign(face, options.flip_cutter_side);
        FillInfo(path, loaded, face, info);
        info->ruling.clear();
        return Status::Ok();
      });
}

Status WriteCadPatches(const std::string& path,
                       const std::vector<CadPatch>& patches,
                       const CadWriteOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(path + ": " + why);
  if (!IsCadSurfacePath(path))
    return Status::Error(path + ": not a .stp/.step/.igs/.iges name");
  return GuardOcct(path, [&]() {
    SilenceOcct();
    TopoDS_Shape shape;
    if (patches.empty()) {
      shape = BRepBuilderAPI_MakeVertex(gp_Pnt(0, 0, 0)).Vertex();
    } else if (patches.size() == 1) {
      TopoDS_Face face;
      Status s = PatchFace(patches[0], 0, &face);
      if (!s.ok()) return Status::Error(path + ": " + s.message());
      shape = face;
    } else {
      TopoDS_Compound compound;
      BRep_Builder builder;
      builder.MakeCompound(compound);
      for (size_t i = 0; i < patches.size(); ++i) {
        TopoDS_Face face;
        Status s = PatchFace(patches[i], static_cast<int>(i), &face);
        if (!s.ok()) return Status::Error(path + ": " + s.message());
        builder.Add(compound, face);
      }
      shape = compound;
    }
    return WriteShape(path, shape, options);
  });
}

Status WriteCadRuledSurface(const std::string& path,
                            const RuledSurface& surface,
                            const CadWriteOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(path + ": " + why);
  return GuardOcct(path, [&]() {
    Handle(Geom_BSplineCurve) rails[2];
    for (int r = 0; r < 2; ++r) {
      const BSplineCurve& rail = surface.rail(r);
      const int n = static_cast<int>(rail.control_points().size());
      TColgp_Array1OfPnt poles(1, n);
      for (int i = 0; i < n; ++i)
        poles.SetValue(i + 1, ToGp(rail.control_points()[i]));
      TColStd_Array1OfReal knots(1, 1);
      TColStd_Array1OfInteger mults(1, 1);
      ToOcctKnots(rail.knots(), &knots, &mults);
      rails[r] = new Geom_BSplineCurve(poles, knots, mults, rail.degree());
    }
    GeomFill_BSplineCurves filler(rails[0], rails[1], GeomFill_StretchStyle);
    Handle(Geom_BSplineSurface) bs = filler.Surface();
    // Put the rails along u, rail 0 at v = 0 and u running as rail 0 does.
    if (!ExactlyRuled(bs, false)) bs->ExchangeUV();
    const Eigen::Vector3d c0 = ToEigen(rails[0]->Pole(1));
    auto near = [&](int i, int j) {
      return (ToEigen(bs->Pole(i, j)) - c0).norm() < kPoleTolMm;
    };
    if (!near(1, 1) && near(1, bs->NbVPoles())) bs->VReverse();
    if (!near(1, 1) && near(bs->NbUPoles(), 1)) bs->UReverse();
    if (!near(1, 1) || !ExactlyRuled(bs, false)) {
      return Status::Error(path +
                           ": OCCT's ruled surface between the rails of " +
                           surface.name() + " does not start at rail 0");
    }
    BRepBuilderAPI_MakeFace make(bs, 1e-7);
    if (!make.IsDone())
      return Status::Error(path + ": OCCT could not make a face");
    TopoDS_Face face = make.Face();
    if (surface.cutter_side() == CutterSide::kNegative) face.Reverse();
    SilenceOcct();
    return WriteShape(path, face, options);
  });
}

}  // namespace tpopt
