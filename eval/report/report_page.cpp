#include "eval/report/report_page.h"

#include "core/error.h"
#include "eval/regression/report_format.h"
#include "eval/report/report_assets.h"
#include "io/atomic_file.h"

namespace slamkit::eval {
namespace {

// Text inside <script> ends at the first "</script": every "</" becomes "<\/", which means the
// same in JavaScript strings and in JSON.
std::string inside_script(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += '\\';
  }
  return out;
}

// The template with each {{name}} replaced; the substituted texts are not scanned again.
std::string fill_template(std::string_view page,
                          const std::vector<std::pair<std::string, std::string>>& values) {
  std::string out;
  size_t at = 0;
  while (true) {
    const size_t open = page.find("{{", at);
    if (open == std::string_view::npos) break;
    const size_t close = page.find("}}", open);
    out.append(page.substr(at, open - at));
    const std::string_view name = page.substr(open + 2, close - open - 2);
    for (const auto& [key, value] : values)
      if (key == name) out += value;
    at = close + 2;
  }
  out.append(page.substr(at));
  return out;
}

}  // namespace

std::string render_report_page(const nlohmann::json& data, const std::string& title) {
  return fill_template(report_assets::page_html,
                       {{"title", regress::escape_xml(title)},
                        {"style", std::string(report_assets::page_css)},
                        {"three", inside_script(report_assets::three_js)},
                        {"orbit_controls", inside_script(report_assets::orbit_controls_js)},
                        {"data", inside_script(data.dump())},
                        {"script", inside_script(report_assets::page_js)}});
}

ReportSummary write_report(const std::vector<std::filesystem::path>& run_dirs,
                           const std::filesystem::path& out, const ReportOptions& options) {
  std::vector<RunFolder> runs;
  std::vector<PlyCloud> maps, meshes;
  ReportSummary summary;
  std::string title;
  for (const std::filesystem::path& dir : run_dirs) {
    RunFolder& run = runs.emplace_back(read_run_folder(dir));
    maps.push_back(run.map ? read_ply_cloud(*run.map) : PlyCloud{});
    summary.map_points += maps.back().points.size();
    // A budget of 0 shows no mesh: the file (tens of MB) is not read.
    const bool show_mesh = run.mesh && options.mesh_triangle_budget > 0;
    meshes.push_back(show_mesh ? read_ply_cloud(*run.mesh) : PlyCloud{});
    summary.mesh_triangles += meshes.back().triangles.size();
    for (const std::string& note : run.notes) summary.notes.push_back(run.name + ": " + note);
    title += (title.empty() ? "" : " vs ") + run.name;
  }
  const nlohmann::json data = report_data(runs, maps, meshes, options);
  for (const nlohmann::json& run : data["runs"]) {
    if (run.contains("map")) summary.map_points_shown += run["map"]["count"].get<size_t>();
    if (run.contains("mesh")) summary.mesh_triangles_shown += run["mesh"]["count"].get<size_t>();
  }
  const std::string page = render_report_page(data, "slamkit report: " + title);
  summary.bytes = page.size();
  write_file_atomically(out, [&](std::ostream& stream) { stream << page; });
  return summary;
}

}  // namespace slamkit::eval
