// Surfaces from CAD files: B-spline faces of STEP (.stp, .step) and IGES
// (.igs, .iges) files, read and written through OpenCASCADE.
//
// This is the only unit that includes OpenCASCADE (built as the tpopt_cad
// library). Configured with -DTPOPT_WITH_OCCT=OFF it is replaced by
// cad_io_unavailable.cc, whose functions fail with a message saying so.
//
// Coordinates come back in mm whatever the file's length unit: OCCT's
// readers convert STEP's length unit and IGES's unit flag to mm.
#ifndef TPOPT_MODEL_CAD_IO_H_
#define TPOPT_MODEL_CAD_IO_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/geometry/bspline_surface.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"

namespace tpopt {

// True when the path ends in .stp, .step, .igs or .iges (any case).
bool IsCadSurfacePath(const std::string& path);

// False when tpopt was built without OpenCASCADE.
bool CadIoAvailable();

struct CadReadOptions {
  // The face to read, 0-based in the file's order (TopExp_Explorer). -1:
  // the file must hold exactly one face; otherwise the error lists them.
  int face_index = -1;
  // The face's parameter direction that is the ruling: "u", "v", or "" to
  // detect it (the direction of degree 1 with two poles; for a face that is
  // not exactly ruled, the direction whose ruled approximation is closer).
  std::string ruling;
  // The cutter lies on the side of the face's outward normal (its surface
  // normal, turned when the face is REVERSED); true puts it on the other.
  bool flip_cutter_side = false;
  // A face that is not exactly ruled is replaced by the ruled surface
  // between its two boundary curves across the ruling, and refused when
  // that is farther than this from the face, mm. Default 0.01 mm: a
  // tenth of a common flank-milling tolerance.
  double max_ruled_deviation_mm = 0.01;

  bool IsValid(std::string* why) const;
};

// One face of a file, for listings and reports.
struct CadFaceSummary {
  int index = 0;
  std::string surface_type;  // OCCT's class name, e.g. "Geom_BSplineSurface"
  int degree_u = 0, degree_v = 0;  // 0 when not a B-spline or Bezier
  int poles_u = 0, poles_v = 0;
  bool rational = false;
  // One line: "face 1: Geom_BSplineSurface, degree 3 x 1, 5 x 2 poles".
  std::string Describe() const;
};

// What a read did, for the run's report.
struct CadSurfaceInfo {
  std::string file;
  std::string length_unit;  // the file's, e.g. "MM", "INCH"
  int face_count = 0;
  CadFaceSummary face;
  std::string ruling;        // "u" or "v", in the file's parameters
  bool exact_ruled = false;  // the face is the RuledSurface exactly
  // Max distance from the face to the RuledSurface, over a 41 x 41 grid of
  // face points, mm (0 when exact_ruled).
  double ruled_deviation_mm = 0.0;
  // The face's boundary lies inside its surface's natural bounds; tpopt
  // uses the natural bounds.
  bool trimmed = false;
  bool face_reversed = false;  // the face's orientation is REVERSED
};

// Lists the faces of a STEP or IGES file. Errors name the file.
Status ListCadFaces(const std::string& path,
                    std::vector<CadFaceSummary>* faces);

// Reads one face as a RuledSurface r(u, v) = (1 - v) C1(u) + v C2(u): rail 0
// is the boundary at the start of the ruling parameter, rail 1 at its end.
// A B-spline or Bezier face of degree 1 with two poles along the ruling, or
// a linear extrusion (over the face's extent) of a B-spline, is taken
// exactly; any other B-spline face through its boundary curves, within
// options.max_ruled_deviation_mm. Rational faces are refused by name (the
// rails are non-rational B-splines). Errors name the file and the face.
Status ReadCadRuledSurface(const std::string& path,
                           const CadReadOptions& options, RuledSurface* surface,
                           CadSurfaceInfo* info);

// Reads one face as a non-rational B-spline surface of degree 1 to 3 each
// way (the free-form surfaces of stripwidth and pencil), in the file's own
// parameters. *cutter_side_sign is +1 when the cutter lies on the side of
// S_u x S_v. options.ruling and max_ruled_deviation_mm are not used.
Status ReadCadBSplineSurface(const std::string& path,
                             const CadReadOptions& options,
                             BSplineSurface* surface, double* cutter_side_sign,
                             CadSurfaceInfo* info);

// A tensor-product face to write, in mm: knots flat (clamped, each knot
// repeated by its multiplicity), poles[i][j] with i along u. Empty weights
// write a non-rational surface. A Bezier face has no knots (degree =
// poles - 1 each way). `as_plane` writes instead the plane through
// poles[0][0] spanned towards poles.back()[0] and poles[0].back(), a face
// that is no B-spline (for tests of refusal).
struct CadPatch {
  int degree_u = 3, degree_v = 1;
  std::vector<double> knots_u, knots_v;
  std::vector<std::vector<Eigen::Vector3d>> poles;
  std::vector<std::vector<double>> weights;
  bool bezier = false;
  bool as_plane = false;
  bool reversed = false;  // write the face REVERSED
  // Non-zero: write instead the linear extrusion (OCCT's
  // Geom_SurfaceOfLinearExtrusion) of the curve through poles[i][0] (degree_u,
  // knots_u) by this vector, mm.
  Eigen::Vector3d extrusion_mm = Eigen::Vector3d::Zero();
  // The face keeps the first trim_u of the u range (1: the whole surface;
  // less: a trimmed face).
  double trim_u = 1.0;
};

// The patch of a B-spline surface (its normalised knots and its net).
inline CadPatch PatchOf(const BSplineSurface& surface) {
  CadPatch patch;
  patch.degree_u = surface.degree_u();
  patch.degree_v = surface.degree_v();
  patch.knots_u = surface.knots_u();
  patch.knots_v = surface.knots_v();
  patch.poles.assign(surface.rows(),
                     std::vector<Eigen::Vector3d>(surface.cols()));
  for (int i = 0; i < surface.rows(); ++i) {
    for (int j = 0; j < surface.cols(); ++j)
      patch.poles[i][j] = surface.control_point(i, j);
  }
  return patch;
}

struct CadWriteOptions {
  // The file's length unit: "MM" or "INCH" (coordinates are converted).
  std::string length_unit = "MM";
  // The STEP header's time stamp, fixed so that a file is reproducible.
  std::string time_stamp = "2026-01-01T00:00:00";

  bool IsValid(std::string* why) const;
};

// Writes the faces (a compound when more than one; none writes a single
// vertex, a file without a surface) as STEP or IGES by the extension, whole
// or not at all.
Status WriteCadPatches(const std::string& path,
                       const std::vector<CadPatch>& patches,
                       const CadWriteOptions& options);

// A RuledSurface as one face (its rails made compatible by OCCT's
// GeomFill_BSplineCurves, exactly), oriented so that ReadCadRuledSurface
// gives back the same rails and cutter side.
Status WriteCadRuledSurface(const std::string& path,
                            const RuledSurface& surface,
                            const CadWriteOptions& options);

}  // namespace tpopt

#endif  // TPOPT_MODEL_CAD_IO_H_
