// The `--html` and `--vtk` outputs of evaluate and smooth: checked before
// the run, so a typo costs no solve, and written after it.
#ifndef TPOPT_APPS_PICTURE_OUTPUTS_H_
#define TPOPT_APPS_PICTURE_OUTPUTS_H_

#include <string>
#include <vector>

#include "apps/html_report.h"
#include "apps/job_io.h"
#include "model/base/status.h"

namespace tpopt {

// Fails (usage) when --vtk is set without a .vtp or .vtk extension.
Status CheckPictureFlags();

// Writes the HTML report of `paths` (one, or before and after) when --html
// is set, and the VTK scene of the last path (the output of a smooth) when
// --vtk is set; each whole or not at all. Errors name the file.
Status WritePictures(const std::string& title, const std::string& command_line,
                     const std::vector<ReportedPath>& paths, const Job& job);

}  // namespace tpopt

#endif  // TPOPT_APPS_PICTURE_OUTPUTS_H_
