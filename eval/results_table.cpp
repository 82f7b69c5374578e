#include "eval/results_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

#include "io/atomic_file.h"

namespace slamkit::eval {
namespace {

using nlohmann::json;

enum class Unit { kMetre, kDegree, kCount };

struct Column {
  const char* path;  // in metrics.json
  const char* csv;   // CSV header: the unit in the name, for scripts
  const char* text;  // Markdown header
  Unit unit;
};

const Column kColumns[] = {
    {"ate.rmse", "ate_rmse_m", "ATE RMSE [m]", Unit::kMetre},
    {"ate.mean", "ate_mean_m", "ATE mean [m]", Unit::kMetre},
    {"ate.median", "ate_median_m", "ATE median [m]", Unit::kMetre},
    {"ate.std", "ate_std_m", "ATE std [m]", Unit::kMetre},
    {"ate.min", "ate_min_m", "ATE min [m]", Unit::kMetre},
    {"ate.max", "ate_max_m", "ATE max [m]", Unit::kMetre},
    {"rpe.trans.rmse", "rpe_trans_rmse_m", "RPE trans. RMSE [m]", Unit::kMetre},
    {"rpe.rot_deg.rmse", "rpe_rot_rmse_deg", "RPE rot. RMSE [deg]", Unit::kDegree},
    {"ate.pairs", "ate_pairs", "ATE pairs", Unit::kCount},
    {"rpe.pairs", "rpe_pairs", "RPE pairs", Unit::kCount},
};
constexpr size_t kColumnCount = std::size(kColumns);

bool is_rmse(const Column& c) { return std::string(c.path).find(".rmse") != std::string::npos; }

std::optional<double> number(const EvaluatedRun& run, const Column& c) {
  const json* v = metric_value(run, c.path);
  if (!v || !v->is_number()) return std::nullopt;
  return v->get<double>();
}

// Decimals giving three significant digits of the smallest non-zero RMSE in `unit`.
int decimals_for(const std::vector<EvaluatedRun>& runs, Unit unit) {
  double smallest = 0;
  for (const EvaluatedRun& run : runs)
    for (const Column& c : kColumns)
      if (c.unit == unit && is_rmse(c))
        if (const auto v = number(run, c); v && *v > 0 && (smallest == 0 || *v < smallest))
          smallest = *v;
  if (smallest == 0) return 3;
  return std::clamp(2 - int(std::floor(std::log10(smallest))), 0, 6);
}

// The rounded cells of the Markdown and LaTeX tables, [run][column] ("" = missing), and which
// are the lowest of their error column.
struct RoundedTable {
  std::vector<std::vector<std::string>> text;
  std::vector<std::vector<bool>> best;
};

RoundedTable round_table(const std::vector<EvaluatedRun>& runs) {
  const int metre_decimals = decimals_for(runs, Unit::kMetre);
  const int degree_decimals = decimals_for(runs, Unit::kDegree);
  RoundedTable t{std::vector<std::vector<std::string>>(runs.size()),
                 std::vector<std::vector<bool>>(runs.size(), std::vector<bool>(kColumnCount))};
  for (size_t r = 0; r < runs.size(); ++r)
    for (const Column& c : kColumns) {
      const auto v = number(runs[r], c);
      char text[128] = "";  // inputs are within 1e100, so are the errors: 101 digits
      if (v && c.unit == Unit::kCount) std::snprintf(text, sizeof text, "%.0f", *v);
      if (v && c.unit != Unit::kCount)
        std::snprintf(text, sizeof text, "%.*f",
                      c.unit == Unit::kMetre ? metre_decimals : degree_decimals, *v);
      t.text[r].push_back(text);
    }
  // The best is judged on the printed digits: values that print alike are all bold.
  for (size_t k = 0; k < kColumnCount; ++k) {
    if (kColumns[k].unit == Unit::kCount) continue;
    std::optional<double> lowest;
    size_t values = 0;
    for (const auto& row : t.text)
      if (!row[k].empty()) {
        lowest = std::min(lowest.value_or(HUGE_VAL), std::stod(row[k]));
        ++values;
      }
    if (values < 2) continue;  // a lone value is no best
    for (size_t r = 0; r < runs.size(); ++r)
      t.best[r][k] = !t.text[r][k].empty() && std::stod(t.text[r][k]) == lowest;
  }
  return t;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

// Characters that would end the cell (|) or start emphasis or code in a Markdown table.
std::string markdown_escaped(const std::string& s) {
  std::string out;
  for (char ch : s) {
    if (std::string("\\|*_`").find(ch) != std::string::npos) out += '\\';
    out += ch;
  }
  return out;
}

std::string latex_escaped(const std::string& s) {
  // LaTeX's special characters, and those the default OT1 font encoding prints as other glyphs.
  static const std::map<char, std::string> kEscapes = {{'\\', "\\textbackslash{}"},
                                                       {'~', "\\textasciitilde{}"},
                                                       {'^', "\\textasciicircum{}"},
                                                       {'|', "\\textbar{}"},
                                                       {'<', "\\textless{}"},
                                                       {'>', "\\textgreater{}"},
                                                       {'&', "\\&"},
                                                       {'%', "\\%"},
                                                       {'$', "\\$"},
                                                       {'#', "\\#"},
                                                       {'_', "\\_"},
                                                       {'{', "\\{"},
                                                       {'}', "\\}"}};
  std::string out;
  for (char ch : s) {
    const auto escape = kEscapes.find(ch);
    out += escape != kEscapes.end() ? escape->second : std::string(1, ch);
  }
  return out;
}

}  // namespace

std::string results_table_csv(const std::vector<EvaluatedRun>& runs) {
  std::ostringstream out;
  out << "run";
  for (const Column& c : kColumns) out << "," << c.csv;
  out << "\n";
  for (const EvaluatedRun& run : runs) {
    out << csv_field(run.name);
    for (const Column& c : kColumns) {
      const json* v = metric_value(run, c.path);
      out << "," << (v ? v->dump() : "");
    }
    out << "\n";
  }
  return out.str();
}

std::string results_table_markdown(const std::vector<EvaluatedRun>& runs) {
  const RoundedTable t = round_table(runs);
  std::ostringstream out;
  out << "| Run |";
  for (const Column& c : kColumns) out << " " << c.text << " |";
  out << "\n|:---|";
  for (size_t k = 0; k < kColumnCount; ++k) out << "---:|";
  out << "\n";
  for (size_t r = 0; r < runs.size(); ++r) {
    out << "| " << markdown_escaped(runs[r].name) << " |";
    for (size_t k = 0; k < kColumnCount; ++k) {
      const std::string& cell = t.text[r][k];
      out << " " << (cell.empty() ? "–" : t.best[r][k] ? "**" + cell + "**" : cell) << " |";
    }
    out << "\n";
  }
  return out.str();
}

std::string results_table_latex(const std::vector<EvaluatedRun>& runs) {
  const RoundedTable t = round_table(runs);
  // Grouped headers (ATE, RPE RMSE, pairs) keep the columns narrow enough for a paper.
  std::ostringstream out;
  out << "% ATE and RPE per run, written by slamkit eval compare; needs \\usepackage{booktabs}\n"
      << "\\begin{tabular}{l" << std::string(kColumnCount, 'r') << "}\n"
      << "\\toprule\n"
      << " & \\multicolumn{6}{c}{ATE [m]} & \\multicolumn{2}{c}{RPE RMSE}"
      << " & \\multicolumn{2}{c}{pairs} \\\\\n"
      << "\\cmidrule(lr){2-7} \\cmidrule(lr){8-9} \\cmidrule(lr){10-11}\n"
      << "Run & RMSE & mean & median & std & min & max & trans. [m] & rot. [$^\\circ$]"
      << " & ATE & RPE \\\\\n"
      << "\\midrule\n";
  for (size_t r = 0; r < runs.size(); ++r) {
    out << latex_escaped(runs[r].name);
    for (size_t k = 0; k < kColumnCount; ++k) {
      const std::string& cell = t.text[r][k];
      out << " & " << (cell.empty() ? "--" : t.best[r][k] ? "\\textbf{" + cell + "}" : cell);
    }
    out << " \\\\\n";
  }
  out << "\\bottomrule\n\\end{tabular}\n";
  return out.str();
}

void write_results_tables(const std::filesystem::path& dir, const std::vector<EvaluatedRun>& runs) {
  const auto write = [&](const char* name, const std::string& text) {
    write_file_atomically(dir / name, [&](std::ostream& out) { out << text; });
  };
  write("table.csv", results_table_csv(runs));
  write("table.md", results_table_markdown(runs));
  write("table.tex", results_table_latex(runs));
}

}  // namespace slamkit::eval
