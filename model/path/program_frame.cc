#include "model/path/program_frame.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace tpopt {
namespace {

// The numbers after the slash of an APT record, or false when one is not
// a number.
bool RecordNumbers(const std::string& text, std::vector<double>* numbers) {
  numbers->clear();
  const size_t slash = text.find('/');
  std::string body = text.substr(slash + 1);
  for (char& c : body) {
    if (c == '$' || c == '\n') c = ' ';
  }
  std::stringstream in(body);
  std::string field;
  while (std::getline(in, field, ',')) {
    const size_t b = field.find_first_not_of(" \t\r");
    if (b == std::string::npos) return false;
    const size_t e = field.find_last_not_of(" \t\r");
    field = field.substr(b, e - b + 1);
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(field, &used);
    } catch (...) {
      return false;
    }
    if (used != field.size() || !std::isfinite(value)) return false;
    numbers->push_back(value);
  }
  return true;
}

std::string Word(const std::string& text) {
  const size_t b = text.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const size_t slash = text.find('/', b);
  if (slash == std::string::npos) return "";
  std::string word = text.substr(b, slash - b);
  while (!word.empty() && (word.back() == ' ' || word.back() == '\t')) word.pop_back();
  return word;
}

}  // namespace

Status ReadProgramFrame(const Program& program, ProgramFrame* frame) {
  *frame = ProgramFrame();
  bool have = false;
  for (const ProgramBlock& block : program.blocks) {
    const std::string word = Word(block.text);
    if (word != "MSYS" && word != "CSYS") continue;
    const std::string at = program.file + ":" + std::to_string(block.line) + ": ";
    std::vector<double> n;
    if (!RecordNumbers(block.text, &n)) {
      return Status::Error(at + "'" + block.text + "': " + word + " takes numbers only");
    }
    if (word == "CSYS") {
      const std::vector<double> identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
      if (n != identity) {
        return Status::Error(at + "'" + block.text +
                             "': a CSYS other than the identity is not applied (its direction "
                             "is not settled here), so the moves cannot be judged against a "
                             "surface");
      }
      continue;
    }
    if (n.size() != 9) {
      return Status::Error(at + "'" + block.text + "': MSYS takes 9 numbers (origin, X axis, Y "
                                                   "axis), not " + std::to_string(n.size()));
    }
    const Eigen::Vector3d x(n[3], n[4], n[5]), y(n[6], n[7], n[8]);
    if (std::abs(x.norm() - 1) > 1e-4 || std::abs(y.norm() - 1) > 1e-4 ||
        std::abs(x.dot(y)) > 1e-4) {
      return Status::Error(at + "'" + block.text +
                           "': the MSYS X and Y axes must be unit and perpendicular");
    }
    // The record's 7 decimals leave the axes a few 1e-8 off orthonormal.
    ProgramFrame f;
    const Eigen::Vector3d ux = x.normalized();
    const Eigen::Vector3d uy = (y - y.dot(ux) * ux).normalized();
    f.rotation.col(0) = ux;
    f.rotation.col(1) = uy;
    f.rotation.col(2) = ux.cross(uy);
    f.origin_mm = Eigen::Vector3d(n[0], n[1], n[2]) * block.mm_per_unit;
    f.source_line = block.line;
    if (have && (!f.rotation.isApprox(frame->rotation, 1e-12) ||
                 !(f.origin_mm - frame->origin_mm).isZero(1e-9))) {
      return Status::Error(at + "'" + block.text + "': a second MSYS names another frame than "
                           "line " + std::to_string(frame->source_line) +
                           "'s; moves in several frames are not judged against one surface");
    }
    *frame = f;
    have = true;
  }
  return Status::Ok();
}

Status MoveRuledSurface(const RuledSurface& surface, const Eigen::Matrix3d& rotation,
                        const Eigen::Vector3d& translation_mm, RuledSurface* moved) {
  BSplineCurve rails[2];
  for (int i = 0; i < 2; ++i) {
    const BSplineCurve& rail = surface.rail(i);
    std::vector<Eigen::Vector3d> points = rail.control_points();
    for (Eigen::Vector3d& q : points) q = rotation * q + translation_mm;
    RETURN_IF_ERROR(BSplineCurve::Create(rail.degree(), rail.knots(), std::move(points),
                                         surface.name() + ": rail " + std::to_string(i),
                                         &rails[i]));
  }
  *moved = RuledSurface(surface.name(), rails[0], rails[1], surface.cutter_side());
  return Status::Ok();
}

}  // namespace tpopt
