#include "eval/sweep/sweep_report.h"

#include <cstdio>
#include <sstream>

#include "eval/plotting.h"
#include "eval/regression/baseline.h"
#include "eval/regression/comparison.h"
#include "eval/regression/report_format.h"

namespace slamkit::sweep {
namespace {

namespace fs = std::filesystem;
using regress::escape_markdown;
using regress::escape_xml;
using regress::MetricInfo;

// A table as text cells, written as Markdown or HTML alike.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> numeric;  // per column: right-aligned
};

void write_markdown_table(std::ostream& out, const Table& t) {
  out << "|";
  for (const std::string& h : t.header) out << " " << escape_markdown(h) << " |";
  out << "\n|";
  for (size_t c = 0; c < t.header.size(); ++c) out << (t.numeric[c] ? "---:|" : "---|");
  out << "\n";
  for (const auto& row : t.rows) {
    out << "|";
    for (const std::string& cell : row) out << " " << escape_markdown(cell) << " |";
    out << "\n";
  }
}

void write_html_table(std::ostream& out, const Table& t) {
  out << "<table><tr>";
  for (const std::string& h : t.header) out << "<th>" << escape_xml(h) << "</th>";
  out << "</tr>\n";
  for (const auto& row : t.rows) {
    out << "<tr>";
    for (size_t c = 0; c < row.size(); ++c)
      out << (t.numeric[c] ? "<td class=\"num\">" : "<td>") << escape_xml(row[c]) << "</td>";
    out << "</tr>\n";
  }
  out << "</table>\n";
}

std::string seed_text(const Job& job) { return job.seed ? std::to_string(*job.seed) : "-"; }

std::string value_text(const MetricInfo& m, const std::optional<double>& v) {
  return v ? regress::format_value(m, *v) : "–";
}

std::string headline(const SweepResults& r) {
  const int total = int(r.jobs.size()), finished = r.finished();
  const SweepStatus& s = r.status;
  std::string text = finished == total ? "COMPLETE" : "INCOMPLETE";
  text += ": " + std::to_string(finished) + " of " + std::to_string(total) + " runs finished";
  if (finished < total)
    text += "; " + std::to_string(s.count(TaskCategory::kFailed)) + " failed, " +
            std::to_string(s.count(TaskCategory::kMissing)) + " missing, " +
            std::to_string(s.count(TaskCategory::kPending) + s.count(TaskCategory::kRunning)) +
            " queued or running";
  return text;
}

std::string shape_line(const SweepResults& r) {
  const Sweep& sw = r.plan->sweep;
  return "Sweep " + sw.file.string() + ": suite " + sw.suite.name + ", " +
         std::to_string(sw.suite.entries.size()) + " entries x " +
         std::to_string(sw.variants.size()) + " variants x " +
         (sw.seeds.empty() ? std::string("the suite's seeds")
                           : std::to_string(sw.seeds.size()) + " seeds") +
         " = " + std::to_string(r.jobs.size()) + " runs; slamkit " + regress::slamkit_version() +
         " on " + regress::machine_description() + ", " + utc_now_iso() + ".";
}

Table ranking_table(const SweepResults& r) {
  Table t{{"metric", "best variant", "mean", "runner-up", "mean", "margin", "runs compared"},
          {},
          {false, false, true, false, true, true, true}};
  for (const Ranking& k : r.rankings) {
    const MetricInfo& m = *k.metric;
    const VariantScore& best = k.scores.front();
    std::vector<std::string> row = {m.label, best.variant, mean_text(m, best.mean)};
    if (k.scores.size() > 1) {
      const VariantScore& next = k.scores[1];
      regress::MetricComparison margin;
      margin.metric = &m;
      margin.value = next.mean;
      margin.baseline = best.mean;
      row.insert(row.end(), {next.variant, mean_text(m, next.mean),
                             next.mean == best.mean ? "tie" : regress::format_delta(margin)});
    } else {
      row.insert(row.end(), {"–", "–", "–"});
    }
    row.push_back(std::to_string(k.pairs) + " per variant");
    t.rows.push_back(row);
  }
  return t;
}

Table ate_table(const SweepResults& r) {
  const MetricInfo& ate = *regress::find_metric("ate_rmse");
  Table t{{"variant"}, {}, {false}};
  for (const regress::SuiteEntry& e : r.plan->sweep.suite.entries) {
    t.header.push_back(e.name);
    t.numeric.push_back(true);
  }
  for (const Variant& v : r.plan->sweep.variants) {
    std::vector<std::string> row = {v.name};
    for (const regress::SuiteEntry& e : r.plan->sweep.suite.entries)
      row.push_back(value_text(ate, r.mean("ate_rmse", v.name, e.name)));
    t.rows.push_back(row);
  }
  return t;
}

Table unfinished_table(const SweepResults& r) {
  Table t{{"index", "run", "state", "Slurm state", "log"}, {}, {true, false, false, false, false}};
  for (const JobResult& j : r.jobs) {
    if (j.status.category == TaskCategory::kDone && j.error.empty()) continue;
    const std::string state =
        j.error.empty() ? category_name(j.status.category) : "failed: " + j.error;
    const std::string slurm =
        j.status.slurm.state.empty() ? "–" : j.status.slurm.state + " (" + j.status.slurm.job + ")";
    t.rows.push_back({std::to_string(j.job->index), j.job->label(), state, slurm,
                      j.status.log.empty() ? "–" : j.status.log.string()});
  }
  return t;
}

// Every metric that some run has, in report order.
std::vector<const MetricInfo*> present_metrics(const SweepResults& r) {
  std::vector<const MetricInfo*> present;
  for (const MetricInfo& m : regress::tracked_metrics())
    for (const JobResult& j : r.jobs)
      if (j.metrics.count(m.key)) {
        present.push_back(&m);
        break;
      }
  return present;
}

Table runs_table(const SweepResults& r) {
  Table t{{"index", "variant", "entry", "seed"}, {}, {true, false, false, true}};
  const auto metrics = present_metrics(r);
  for (const MetricInfo* m : metrics) {
    t.header.push_back(m->label);
    t.numeric.push_back(true);
  }
  for (const JobResult& j : r.jobs) {
    std::vector<std::string> row = {std::to_string(j.job->index), j.job->variant, j.job->entry,
                                    seed_text(*j.job)};
    for (const MetricInfo* m : metrics) {
      const auto it = j.metrics.find(m->key);
      row.push_back(it == j.metrics.end() ? "–" : regress::format_value(*m, it->second));
    }
    t.rows.push_back(row);
  }
  return t;
}

std::string full_precision(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

void write_runs_csv(const fs::path& file, const SweepResults& r) {
  std::ofstream out = regress::open_output(file);
  out << "index,entry,variant,seed,state";
  for (const MetricInfo& m : regress::tracked_metrics()) out << "," << m.key;
  out << "\n";
  for (const JobResult& j : r.jobs) {
    out << j.job->index << "," << j.job->entry << "," << j.job->variant << "," << seed_text(*j.job)
        << "," << category_name(j.status.category);
    for (const MetricInfo& m : regress::tracked_metrics()) {
      out << ",";
      if (const auto it = j.metrics.find(m.key); it != j.metrics.end())
        out << full_precision(it->second);
    }
    out << "\n";
  }
}

void write_ate_csv(const fs::path& file, const SweepResults& r) {
  std::ofstream out = regress::open_output(file);
  out << "variant";
  for (const regress::SuiteEntry& e : r.plan->sweep.suite.entries) out << "," << e.name;
  out << "\n";
  for (const Variant& v : r.plan->sweep.variants) {
    out << v.name;
    for (const regress::SuiteEntry& e : r.plan->sweep.suite.entries) {
      out << ",";
      if (const auto mean = r.mean("ate_rmse", v.name, e.name)) out << full_precision(*mean);
    }
    out << "\n";
  }
}

const char* kAteNote =
    "ATE RMSE, mean over the seeds; in the heatmap each sequence's colour is relative to its best "
    "variant.";

void write_markdown(const fs::path& file, const SweepResults& r, const SweepReportFiles& files) {
  std::ofstream out = regress::open_output(file);
  const Sweep& sw = r.plan->sweep;
  out << "# Sweep report: " << sw.name << "\n\n";
  if (!sw.description.empty()) out << sw.description << "\n\n";
  out << shape_line(r) << "\n\n**" << headline(r) << "**\n\n";
  out << "## Best variant per metric\n\n";
  if (r.rankings.empty())
    out << "No run finished for every variant yet: nothing to rank.\n";
  else
    write_markdown_table(out, ranking_table(r));
  out << "\n## ATE over variants x sequences\n\n" << kAteNote << "\n\n";
  write_markdown_table(out, ate_table(r));
  if (!files.heatmap.empty())
    out << "\n![ATE heatmap](" << files.heatmap.filename().string() << ")\n";
  const Table unfinished = unfinished_table(r);
  if (!unfinished.rows.empty()) {
    out << "\n## Missing or failed tasks\n\n";
    write_markdown_table(out, unfinished);
  }
  out << "\n## Runs\n\nRun folders under `runs/<variant>/<entry>/`; every metric at full "
         "precision in `runs.csv`.\n\n";
  write_markdown_table(out, runs_table(r));
}

void write_html(const fs::path& file, const SweepResults& r, const SweepReportFiles& files) {
  std::ofstream out = regress::open_output(file);
  const Sweep& sw = r.plan->sweep;
  out << regress::html_head("slamkit sweep: " + sw.name);
  out << "<h1>Sweep report: " << escape_xml(sw.name) << "</h1>\n";
  if (!sw.description.empty()) out << "<p>" << escape_xml(sw.description) << "</p>\n";
  out << "<p class=\"meta\">" << escape_xml(shape_line(r)) << "</p>\n";
  out << "<div class=\"banner " << (r.finished() == int(r.jobs.size()) ? "pass" : "fail") << "\">"
      << escape_xml(headline(r)) << "</div>\n";
  out << "<h2>Best variant per metric</h2>\n";
  if (r.rankings.empty())
    out << "<p>No run finished for every variant yet: nothing to rank.</p>\n";
  else
    write_html_table(out, ranking_table(r));
  out << "<h2>ATE over variants x sequences</h2>\n<p class=\"meta\">" << escape_xml(kAteNote)
      << "</p>\n";
  write_html_table(out, ate_table(r));
  out << regress::html_image(files.heatmap, "ATE over variants and sequences");
  const Table unfinished = unfinished_table(r);
  if (!unfinished.rows.empty()) {
    out << "<h2 class=\"fail\">Missing or failed tasks</h2>\n";
    write_html_table(out, unfinished);
  }
  out << "<h2>Runs</h2>\n";
  write_html_table(out, runs_table(r));
  out << "</body></html>\n";
}

}  // namespace

SweepReportFiles write_sweep_report(const SweepResults& r) {
  const fs::path dir = r.plan->dir;
  SweepReportFiles files{
      dir / "report.md", dir / "report.html", dir / "runs.csv", dir / "ate_table.csv", {}};
  write_runs_csv(files.runs_csv, r);
  write_ate_csv(files.ate_table, r);
  if (r.finished() > 0)
    if (auto png = eval::draw_plot("plot_sweep_heatmap.py",
                                   {"--table", files.ate_table.string(), "--out", dir.string(),
                                    "--title", r.plan->sweep.name},
                                   dir / "ate_heatmap.png", "ATE heatmap"))
      files.heatmap = *png;
  write_markdown(files.markdown, r, files);
  write_html(files.html, r, files);
  return files;
}

}  // namespace slamkit::sweep
