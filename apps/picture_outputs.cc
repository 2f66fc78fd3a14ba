#include "apps/picture_outputs.h"

#include "apps/deviation_grid.h"
#include "apps/flags.h"
#include "apps/vtk_scene.h"
#include "model/io/atomic_file.h"
#include "model/io/vtk_writer.h"

namespace tpopt {

Status CheckPictureFlags() {
  VtkFormat format;
  if (!FLAGS_vtk.empty() && !VtkFormatOf(FLAGS_vtk, &format)) {
    return Status::Usage("--vtk=" + FLAGS_vtk + " must end in .vtp (VTK XML) or .vtk (legacy)");
  }
  return Status::Ok();
}

Status WritePictures(const std::string& title, const std::string& command_line,
                     const std::vector<ReportedPath>& paths, const Job& job) {
  if (!FLAGS_html.empty()) {
    HtmlReportInputs inputs{title, command_line, paths, &job.machine, FLAGS_feed};
    if (job.controller) inputs.controller = &*job.controller;
    std::string html;
    Status s = RenderHtmlReport(inputs, &html);
    if (!s.ok()) return Status::Error(FLAGS_html + ": " + s.message());
    RETURN_IF_ERROR(WriteFileAtomically(FLAGS_html, html));
  }
  if (!FLAGS_vtk.empty()) {
    const ReportedPath& shown = paths.back();
    const PolyData scene = BuildPathScene(*shown.path, job.cutter, job.surface_or_null(),
                                          DeviationGridOf(*shown.metrics));
    RETURN_IF_ERROR(WritePolyData(FLAGS_vtk, scene));
  }
  return Status::Ok();
}

}  // namespace tpopt
