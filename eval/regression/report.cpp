#include "eval/regression/report.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "eval/regression/report_format.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;

std::string entry_verdict(const EntryResult& e) {
  if (!e.run.ok) return "ERROR";
  if (e.failed()) return "REGRESSED";
  if (!e.baseline) return "no baseline";
  return e.has_warning() ? "pass (warnings)" : "pass";
}

std::string css_class(const std::string& verdict) {
  if (verdict == "ERROR" || verdict == "REGRESSED" || verdict == "MISSING") return "fail";
  if (verdict == "improved") return "improved";
  if (verdict.find("warning") != std::string::npos) return "warn";
  if (verdict == "no baseline" || verdict == "other machine") return "none";
  return "pass";
}

std::string optional_value(const MetricInfo& m, const std::optional<double>& v) {
  return v ? format_value(m, *v) : "–";
}

std::string ate_rmse_text(const EntryResult& e) {
  const auto it = e.metrics.find("ate_rmse");
  return it == e.metrics.end() ? "–" : format_value(*find_metric("ate_rmse"), it->second);
}

std::string reference_text(const EntryResult& e) {
  if (!e.entry->reference) return "";
  return e.entry->reference->system + ": " +
         format_value(*find_metric("ate_rmse"), e.entry->reference->ate_rmse);
}

// The lines about a baseline's origin; says so when its settings differ from this run's.
std::string baseline_origin(const EntryResult& e) {
  if (!e.baseline) return "No baseline yet: `slamkit regress SUITE --update-baselines` writes it.";
  const Provenance& p = e.baseline->provenance;
  std::string text = "Baseline: " + p.version + ", " + p.date + ", " + p.machine +
                     "; settings hash " + p.settings_hash;
  if (!e.settings_hash.empty() && e.settings_hash != p.settings_hash)
    text += " (this run's settings differ: " + e.settings_hash + ")";
  if (!e.baseline_same_machine) text += "; timing not compared: another machine";
  return text + ".";
}

std::string run_line(const EntryResult& e, const std::string& quote) {
  return e.entry->sequence.describe() + "; run folder " + quote + "runs/" + e.entry->name + quote;
}

struct Counts {
  int entries = 0, failed = 0, errors = 0, warnings = 0, no_baseline = 0;
};
Counts count(const SuiteReport& r) {
  Counts c;
  for (const EntryResult& e : r.entries) {
    ++c.entries;
    c.errors += !e.run.ok;
    c.failed += e.run.ok && e.failed();
    c.warnings += e.has_warning();
    c.no_baseline += e.run.ok && !e.baseline;
  }
  return c;
}

std::string headline(const SuiteReport& r) {
  const Counts c = count(r);
  // With --update-baselines the comparison is with the old baselines: what changed.
  std::string text = r.baselines_updated ? "BASELINES UPDATED" : r.failures() ? "FAIL" : "PASS";
  text += ": " + std::to_string(c.entries) + " entries, " + std::to_string(c.failed) +
          " regressed, " + std::to_string(c.errors) + " failed to run, " +
          std::to_string(c.warnings) + " with timing warnings, " + std::to_string(c.no_baseline) +
          " without baseline";
  if (r.baselines_updated) text += "; baselines updated from this run";
  return text;
}

// `page` relative to the folder of the report that links it (so the suite's folder can move).
std::string page_link(const fs::path& report, const fs::path& page) {
  return fs::absolute(page)
      .lexically_normal()
      .lexically_relative(fs::absolute(report).lexically_normal().parent_path())
      .generic_string();
}

}  // namespace

bool EntryResult::failed() const {
  if (!run.ok) return true;
  for (const MetricComparison& c : comparisons)
    if (is_failure(c.verdict)) return true;
  return false;
}

bool EntryResult::has_warning() const {
  for (const MetricComparison& c : comparisons)
    if (c.verdict == Verdict::kWarning) return true;
  return false;
}

int SuiteReport::failures() const {
  int n = 0;
  for (const EntryResult& e : entries) n += e.failed();
  return n;
}

void write_report_markdown(const fs::path& file, const SuiteReport& r) {
  std::ofstream out = open_output(file);
  out << "# Regression report: " << r.suite->name << "\n\n";
  if (!r.suite->description.empty()) out << r.suite->description << "\n\n";
  out << "Suite `" << r.suite->file.string() << "`; slamkit " << r.current.version << " on "
      << r.current.machine << ", " << r.current.date << ".\n\n";
  out << "**" << headline(r) << "**\n\n";
  out << "| entry | sequence | verdict | ATE RMSE | baseline | published |\n"
      << "|---|---|---|---:|---:|---|\n";
  for (const EntryResult& e : r.entries) {
    std::string baseline = "–";
    if (e.baseline && e.baseline->metrics.count("ate_rmse"))
      baseline = format_value(*find_metric("ate_rmse"), e.baseline->metrics.at("ate_rmse"));
    out << "| " << e.entry->name << " | " << escape_markdown(e.entry->sequence.describe()) << " | "
        << entry_verdict(e) << " | " << ate_rmse_text(e) << " | " << baseline << " | "
        << escape_markdown(reference_text(e)) << " |\n";
  }
  for (const EntryResult& e : r.entries) {
    out << "\n## " << e.entry->name << ": " << entry_verdict(e) << "\n\n"
        << escape_markdown(run_line(e, "`")) << ".\n\n";
    if (!e.run.ok) {
      out << "The run failed: " << e.run.error << "\n";
      continue;
    }
    out << baseline_origin(e) << "\n\n";
    out << "| metric | value | baseline | delta | tolerance | verdict |\n"
        << "|---|---:|---:|---:|---:|---|\n";
    for (const MetricComparison& c : e.comparisons) {
      const MetricInfo& m = *c.metric;
      out << "| " << m.label << (m.warn_only ? " (warning only)" : "") << " | "
          << optional_value(m, c.value) << " | " << optional_value(m, c.baseline) << " | "
          << format_delta(c) << " | " << (c.baseline ? format_value(m, c.allowed) : "") << " | "
          << (is_failure(c.verdict) ? "**" : "") << verdict_name(c.verdict)
          << (is_failure(c.verdict) ? "**" : "") << " |\n";
    }
    if (e.entry->reference) out << "\nPublished: " << reference_text(e) << ".\n";
    if (fs::exists(e.run.dir / "report.html"))
      out << "\n[The run's page](" << page_link(file, e.run.dir / "report.html") << ")\n";
    for (const char* plot : {"ate_over_time.png", "trajectory_xy.png"})
      if (fs::exists(e.run.dir / plot))
        out << "\n![" << plot << "](runs/" << e.entry->name << "/" << plot << ")\n";
  }
  if (!r.comparison_plot.empty())
    out << "\n## ATE across entries\n\n![ATE per entry](" << r.comparison_plot.filename().string()
        << ")\n";
  if (!r.history_plot.empty())
    out << "\n## ATE over versions\n\n![ATE over versions](" << r.history_plot.filename().string()
        << ")\n";
}

void write_report_html(const fs::path& file, const SuiteReport& r) {
  std::ofstream out = open_output(file);
  const auto image = [&out](const fs::path& png, const std::string& alt) {
    out << html_image(png, alt);
  };
  out << html_head("slamkit regression: " + r.suite->name);
  out << "<h1>Regression report: " << escape_xml(r.suite->name) << "</h1>\n";
  if (!r.suite->description.empty()) out << "<p>" << escape_xml(r.suite->description) << "</p>\n";
  out << "<p class=\"meta\">Suite " << escape_xml(r.suite->file.string()) << "; slamkit "
      << escape_xml(r.current.version) << " on " << escape_xml(r.current.machine) << ", "
      << escape_xml(r.current.date) << ".</p>\n";
  const char* banner = r.baselines_updated ? "improved" : r.failures() ? "fail" : "pass";
  out << "<div class=\"banner " << banner << "\">" << escape_xml(headline(r)) << "</div>\n";
  out << "<table><tr><th>entry</th><th>sequence</th><th>verdict</th><th>ATE RMSE</th>"
      << "<th>baseline</th><th>published</th></tr>\n";
  for (const EntryResult& e : r.entries) {
    std::string baseline = "–";
    if (e.baseline && e.baseline->metrics.count("ate_rmse"))
      baseline = format_value(*find_metric("ate_rmse"), e.baseline->metrics.at("ate_rmse"));
    const std::string verdict = entry_verdict(e);
    out << "<tr><td><a href=\"#" << e.entry->name << "\">" << e.entry->name << "</a></td><td>"
        << escape_xml(e.entry->sequence.describe()) << "</td><td class=\"" << css_class(verdict)
        << "\">" << verdict << "</td><td class=\"num\">" << ate_rmse_text(e)
        << "</td><td class=\"num\">" << baseline << "</td><td>" << escape_xml(reference_text(e))
        << "</td></tr>\n";
  }
  out << "</table>\n";
  for (const EntryResult& e : r.entries) {
    const std::string verdict = entry_verdict(e);
    out << "<h2 id=\"" << e.entry->name << "\">" << e.entry->name << ": <span class=\""
        << css_class(verdict) << "\">" << verdict << "</span></h2>\n<p class=\"meta\">"
        << escape_xml(run_line(e, "")) << ".</p>\n";
    if (!e.run.ok) {
      out << "<p class=\"fail\">The run failed: " << escape_xml(e.run.error) << "</p>\n";
      continue;
    }
    out << "<p class=\"meta\">" << escape_xml(baseline_origin(e)) << "</p>\n";
    if (fs::exists(e.run.dir / "report.html"))  // the run's own page: map, trajectory, loops
      out << "<p><a href=\"" << escape_xml(page_link(file, e.run.dir / "report.html"))
          << "\">The run's page</a>: its map in 3D, trajectory by error, loops, diagnostics.</p>\n";
    out << "<table><tr><th>metric</th><th>value</th><th>baseline</th><th>delta</th>"
        << "<th>tolerance</th><th>verdict</th></tr>\n";
    for (const MetricComparison& c : e.comparisons) {
      const MetricInfo& m = *c.metric;
      const std::string v = verdict_name(c.verdict);
      out << "<tr><td>" << m.label << (m.warn_only ? " (warning only)" : "")
          << "</td><td class=\"num\">" << optional_value(m, c.value) << "</td><td class=\"num\">"
          << optional_value(m, c.baseline) << "</td><td class=\"num\">" << format_delta(c)
          << "</td><td class=\"num\">" << (c.baseline ? format_value(m, c.allowed) : "")
          << "</td><td class=\"" << css_class(v) << "\">" << v << "</td></tr>\n";
    }
    out << "</table>\n";
    if (e.entry->reference) out << "<p>Published: " << escape_xml(reference_text(e)) << ".</p>\n";
    out << "<div>\n";
    image(e.run.dir / "ate_over_time.png", e.entry->name + ": ATE over time");
    image(e.run.dir / "trajectory_xy.png", e.entry->name + ": trajectory");
    out << "</div>\n";
  }
  if (!r.comparison_plot.empty()) {
    out << "<h2>ATE across entries</h2>\n";
    image(r.comparison_plot, "ATE per entry");
  }
  if (!r.history_plot.empty()) {
    out << "<h2>ATE over versions</h2>\n";
    image(r.history_plot, "ATE over versions");
  }
  out << "</body></html>\n";
}

void write_junit(const fs::path& file, const SuiteReport& r) {
  struct Case {
    std::string classname, name, failure, error, skipped, output;
  };
  std::vector<Case> cases;
  for (const EntryResult& e : r.entries) {
    const std::string classname = r.suite->name + "." + e.entry->name;
    Case run{classname, "run", "", "", "", e.entry->sequence.describe()};
    if (!e.run.ok) run.error = e.run.error;
    cases.push_back(run);
    for (const MetricComparison& c : e.comparisons) {
      const MetricInfo& m = *c.metric;
      Case k{classname, m.key, "", "", "", ""};
      const std::string text = m.label + " " + optional_value(m, c.value) + ", baseline " +
                               optional_value(m, c.baseline) +
                               (c.baseline ? ", tolerance " + format_value(m, c.allowed) : "") +
                               (c.value && c.baseline ? ", delta " + format_delta(c) : "");
      if (is_failure(c.verdict))
        k.failure = text;
      else if (c.verdict == Verdict::kNew)
        k.skipped = "no baseline: " + text;
      else
        k.output = std::string(verdict_name(c.verdict)) + ": " + text;
      cases.push_back(k);
    }
  }
  int failures = 0, errors = 0, skipped = 0;
  for (const Case& c : cases) {
    failures += !c.failure.empty();
    errors += !c.error.empty();
    skipped += !c.skipped.empty();
  }
  std::ofstream out = open_output(file);
  const std::string counts = "tests=\"" + std::to_string(cases.size()) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"" + std::to_string(errors) +
                             "\"";
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"slamkit regress\" "
      << counts << ">\n  <testsuite name=\"" << escape_xml(r.suite->name) << "\" " << counts
      << " skipped=\"" << skipped << "\" timestamp=\"" << escape_xml(r.current.date.substr(0, 19))
      << "\">\n";
  for (const Case& c : cases) {
    out << "    <testcase classname=\"" << escape_xml(c.classname) << "\" name=\""
        << escape_xml(c.name) << "\"";
    if (c.failure.empty() && c.error.empty() && c.skipped.empty() && c.output.empty()) {
      out << "/>\n";
      continue;
    }
    out << ">\n";
    if (!c.failure.empty())
      out << "      <failure type=\"regression\" message=\"" << escape_xml(c.failure) << "\"/>\n";
    if (!c.error.empty())
      out << "      <error type=\"run\" message=\"" << escape_xml(c.error) << "\"/>\n";
    if (!c.skipped.empty()) out << "      <skipped message=\"" << escape_xml(c.skipped) << "\"/>\n";
    if (!c.output.empty()) out << "      <system-out>" << escape_xml(c.output) << "</system-out>\n";
    out << "    </testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
}

}  // namespace slamkit::regress
