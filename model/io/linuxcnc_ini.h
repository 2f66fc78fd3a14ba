// A LinuxCNC machine configuration (INI file) as a tpopt Machine, so that
// tpopt's limits and kinematics and the controller's cannot disagree.
//
// Read from the INI (LinuxCNC 2.9 names):
//  - [KINS] KINEMATICS must name xyzac-trt-kins (its module parameters, such
//    as sparm=identityfirst, are allowed); [TRAJ] COORDINATES, when given,
//    must be XYZAC, so joint n is axis n.
//  - Per axis, the tighter of [JOINT_n] and [AXIS_L]: MIN_LIMIT, MAX_LIMIT,
//    MAX_VELOCITY, MAX_ACCELERATION (mm or deg, per s, s^2). LinuxCNC has no
//    jerk limit, so max_jerk stays unlimited. [TRAJ] LINEAR_UNITS and
//    ANGULAR_UNITS, when given, must be mm and deg.
//  - The kinematics pins xyzac-trt-kins.{x,y,z}-rot-point, .y-offset,
//    .z-offset and .tool-offset from the [HAL] HALCMD lines and from the
//    plain .hal files HALFILE names relative to the INI's folder: `setp PIN
//    V`, and `sets SIGNAL V` for a signal `net` to the pin. Pins never set
//    keep the component's default 0. A tool offset that motion drives at run
//    time (motion.tooloffset.z) is not a constant and is left at 0.
// Unknown sections and keys are ignored, as LinuxCNC does.
#ifndef TPOPT_MODEL_LINUXCNC_INI_H_
#define TPOPT_MODEL_LINUXCNC_INI_H_

#include <istream>
#include <string>

#include "model/machine/machine.h"
#include "model/base/status.h"

namespace tpopt {

// True when `path` names an INI file (ends in .ini, any case).
bool IsLinuxCncIni(const std::string& path);

// Reads `path`; errors name the file, the line and the value.
Status ReadLinuxCncIni(const std::string& path, Machine* machine);

// The same from a stream; `name` is used in messages and `folder` resolves
// relative HALFILE names (empty: HALFILEs are not read).
Status ParseLinuxCncIni(std::istream& in, const std::string& name,
                        const std::string& folder, Machine* machine);

// The tool table the INI `path` names ([EMCIO] TOOL_TABLE, relative to the
// INI's folder, as LinuxCNC resolves it), or empty when it names none.
Status LinuxCncIniToolTable(const std::string& path, std::string* table);

}  // namespace tpopt

#endif  // TPOPT_MODEL_LINUXCNC_INI_H_
