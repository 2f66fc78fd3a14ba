// Where an APT program's frame lies in the CAD model: NX CLSF's MSYS record.
//
// `MSYS/x0,y0,z0,xi,xj,xk,yi,yj,yk` gives the origin and the X and Y axes of
// the machine coordinate system (MCS) in the model's absolute frame; the
// GOTOs after it are in the MCS, and a surface taken from the CAD model is
// in the model's frame. To judge the one against the other, tpopt brings the
// surface into the program's frame (p_program = R^T (p_model - origin)),
// never the moves: the MCS is the frame the machine is set up in (its work
// offset, --part_setup), so its coordinates and the tool axes in it are
// what the kinematics and the travel see, and the program is written back
// as it came.
//
// Refused when judging against a surface (not otherwise: then the frame
// judges nothing): MSYS records that name different frames (the moves would
// be in several frames), an MSYS whose axes are not unit and perpendicular
// to 1e-4, and a CSYS other than the identity 3 x 4 matrix
// (1,0,0,0,0,1,0,0,0,0,1,0), whose direction the documentation consulted
// here does not settle.
#ifndef TPOPT_MODEL_PROGRAM_FRAME_H_
#define TPOPT_MODEL_PROGRAM_FRAME_H_

#include <Eigen/Core>

#include "model/path/program.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"

namespace tpopt {

// p_model = rotation * p_program + origin_mm.
struct ProgramFrame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin_mm = Eigen::Vector3d::Zero();
  // 1-based line of the MSYS record; 0 when the program has none.
  int source_line = 0;

  bool IsIdentity() const {
    return rotation.isApprox(Eigen::Matrix3d::Identity(), 1e-12) && origin_mm.isZero(1e-9);
  }
};

// The frame of an APT program's moves in the model (identity without an
// MSYS). Errors name the file, the line and the value.
Status ReadProgramFrame(const Program& program, ProgramFrame* frame);

// `surface` with every rail control point q moved to rotation * q +
// translation_mm (exact for a B-spline: the curves move rigidly).
Status MoveRuledSurface(const RuledSurface& surface, const Eigen::Matrix3d& rotation,
                        const Eigen::Vector3d& translation_mm, RuledSurface* moved);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PROGRAM_FRAME_H_
