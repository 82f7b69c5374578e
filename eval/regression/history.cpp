// history.csv and the suite's plots, drawn by eval's plot.py.
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "core/error.h"
#include "eval/plotting.h"
#include "eval/regression/report.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;

const char* kFixedColumns = "date,suite,entry,version,settings_hash,run_finished";

// suite,entry,run_finished of every line already in the file.
std::set<std::string> recorded_runs(const fs::path& file) {
  std::set<std::string> runs;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream text(line);
    for (std::string field; std::getline(text, field, ',');) fields.push_back(field);
    if (fields.size() >= 6) runs.insert(fields[1] + "," + fields[2] + "," + fields[5]);
  }
  return runs;
}

// Versions and hashes hold no commas; a description could, so fields are cleaned.
std::string field(std::string text) {
  for (char& c : text)
    if (c == ',' || c == '\n' || c == '"') c = ' ';
  return text;
}

}  // namespace

void append_history(const fs::path& file, const SuiteReport& report) {
  const bool fresh = !fs::exists(file) || fs::file_size(file) == 0;
  const std::set<std::string> known = fresh ? std::set<std::string>() : recorded_runs(file);
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::app);
  if (!out) throw_input_error(file.string(), "cannot append to file");
  if (fresh) {
    out << kFixedColumns;
    for (const MetricInfo& m : tracked_metrics()) out << "," << m.key;
    out << "\n";
  }
  for (const EntryResult& e : report.entries) {
    if (!e.run.ok) continue;
    const std::string key = report.suite->name + "," + e.entry->name + "," + e.run.finished;
    if (known.count(key)) continue;
    out << field(report.current.date) << "," << report.suite->name << "," << e.entry->name << ","
        << field(report.current.version) << "," << e.settings_hash << "," << e.run.finished;
    for (const MetricInfo& m : tracked_metrics()) {
      out << ",";
      if (auto it = e.metrics.find(m.key); it != e.metrics.end()) {
        char value[32];
        std::snprintf(value, sizeof value, "%.9g", it->second);
        out << value;
      }
    }
    out << "\n";
  }
}

void draw_suite_plots(const std::vector<fs::path>& histories, SuiteReport& report) {
  nlohmann::json compare = {{"figure", "compare"},
                            {"out", report.out.string()},
                            {"title", report.suite->name},
                            {"runs", nlohmann::json::array()}};
  for (const EntryResult& e : report.entries)
    if (e.run.ok && fs::exists(e.run.dir / "errors.csv"))
      compare["runs"].push_back({e.entry->name, e.run.dir.string()});
  nlohmann::json figures = nlohmann::json::array();
  if (!compare["runs"].empty()) figures.push_back(compare);
  nlohmann::json history_files = nlohmann::json::array();
  for (const fs::path& history : histories)
    if (fs::exists(history)) history_files.push_back(history.string());
  if (!history_files.empty())
    figures.push_back({{"figure", "history"},
                       {"histories", history_files},
                       {"suite", report.suite->name},
                       {"out", report.out.string()}});
  if (figures.empty()) return;
  const eval::PlotOutcome outcome = eval::draw_figures(figures);
  if (!outcome.drawn) {
    std::cerr << "slamkit: note: no suite plots drawn: " << outcome.problem << "\n";
    return;
  }
  if (!compare["runs"].empty()) report.comparison_plot = report.out / "ate_comparison.png";
  if (!history_files.empty()) report.history_plot = report.out / "ate_history.png";
}

}  // namespace slamkit::regress
