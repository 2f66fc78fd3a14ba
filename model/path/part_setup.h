// Where the part is clamped on the table: the rigid placement of the
// program's frame P (the coordinates of its moves: NX's MCS, the APT part
// frame) in the machine's workpiece frame W (the table at A = C = 0, whose
// origin and axes the machine file's pivot and offsets refer to). On an A/C
// table-table machine the part's offset from the C axis decides all the
// linear motion, so the same program on the same machine needs X Y Z that
// differ with where the part sits.
//
// Convention: p_w = R p_p + t and a_w = R a_p, with R = Rz(rz) Ry(ry) Rx(rx)
// (rotations about W's fixed axes, X first, right-handed, degrees) and t the
// origin of P in W (mm).
//
// NX's MSYS and APT's CSYS records state where the program's frame lies in
// the CAD model, which the machine never sees: the moves are already in
// that frame, so tpopt reads them as P and passes the records through; a
// surface from the CAD model is brought into P by the MSYS
// (model/path/program_frame.h) and placed with the moves.
#ifndef TPOPT_MODEL_PART_SETUP_H_
#define TPOPT_MODEL_PART_SETUP_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct PartSetup {
  // Origin of P in W, mm. Default: P is W.
  Eigen::Vector3d translation_mm = Eigen::Vector3d::Zero();
  // rx, ry, rz in degrees (see the convention above). Default: none.
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();

  // Finite, translation within 1e6 mm, angles within [-360, 360]; `why`
  // names the component and value.
  bool IsValid(std::string* why) const;
  bool IsIdentity() const { return translation_mm.isZero(0.0) && rotation_deg.isZero(0.0); }
  // R, the rotation from P to W.
  Eigen::Matrix3d Rotation() const;
};

// "tx,ty,tz,rx,ry,rz" (mm, deg), as the --part_setup flag takes it.
Status ParsePartSetup(const std::string& text, PartSetup* setup);

// Every pose from P into W (tips and axes).
void PlacePart(const PartSetup& setup, ToolPath* path);

// Every pose and point from W back into P, for writing a program in its
// own frame: the exact inverse of PlacePart.
void UnplacePart(const PartSetup& setup, ToolPath* path);
Eigen::Vector3d UnplacePoint(const PartSetup& setup, const Eigen::Vector3d& p_w);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PART_SETUP_H_
