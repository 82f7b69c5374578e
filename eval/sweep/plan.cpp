#include "eval/sweep/plan.h"

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "eval/metrics/checksum.h"
#include "io/atomic_file.h"
#include "io/path_kind.h"

namespace slamkit::sweep {
namespace {

namespace fs = std::filesystem;

const char* kJobsFile = "jobs.tsv";
const char* kColumns = "index\tentry\tvariant\tseed\trun_folder";

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream text(line);
  for (std::string field; std::getline(text, field, '\t');) fields.push_back(field);
  return fields;
}

std::string seed_text(const std::optional<uint64_t>& seed) {
  return seed ? std::to_string(*seed) : "-";
}

// Fills jobs and entries: entries outermost, then variants, then seeds.
void expand(Plan& plan) {
  const Sweep& sweep = plan.sweep;
  std::vector<std::optional<uint64_t>> seeds(sweep.seeds.begin(), sweep.seeds.end());
  if (seeds.empty()) seeds.push_back(std::nullopt);
  for (const regress::SuiteEntry& entry : sweep.suite.entries)
    for (const Variant& variant : sweep.variants)
      for (const std::optional<uint64_t>& seed : seeds) {
        Job job;
        job.index = int(plan.jobs.size());
        job.entry = entry.name;
        job.variant = variant.name;
        job.seed = seed;
        job.run_folder = fs::path("runs") / variant.name / entry.name;
        if (seed) job.run_folder /= "seed" + std::to_string(*seed);
        plan.jobs.push_back(job);
        plan.entries.push_back(variant_entry(sweep, entry, variant, seed ? &*seed : nullptr));
      }
}

std::string job_row(const Job& job) {
  return std::to_string(job.index) + "\t" + job.entry + "\t" + job.variant + "\t" +
         seed_text(job.seed) + "\t" + job.run_folder.string();
}

}  // namespace

std::string Job::label() const {
  return variant + "/" + entry + (seed ? "/seed" + std::to_string(*seed) : "");
}

regress::RunRequest Plan::request(size_t index) const {
  const Job& job = jobs.at(index);
  fs::path settings = dir / "settings" / job.run_folder.lexically_relative("runs");
  settings += ".yaml";
  return {&entries.at(index), job.label(), dir / job.run_folder, settings};
}

std::vector<regress::RunRequest> Plan::requests() const {
  std::vector<regress::RunRequest> all;
  for (size_t i = 0; i < jobs.size(); ++i) all.push_back(request(i));
  return all;
}

Plan write_plan(const fs::path& sweep_file, const fs::path& dir,
                const regress::SuiteContext& context) {
  Plan plan;
  plan.dir = dir;
  plan.data_dir = context.data_dir;
  plan.sweep = load_sweep(fs::absolute(sweep_file).lexically_normal(), context);
  expand(plan);
  fs::create_directories(dir);
  write_file_atomically(dir / kJobsFile, [&](std::ostream& out) {
    out << "# sweep\t" << plan.sweep.file.string() << "\n"
        << "# sweep_hash\t" << eval::fnv1a64_file(plan.sweep.file) << "\n";
    if (plan.data_dir) out << "# data\t" << fs::absolute(*plan.data_dir).string() << "\n";
    out << kColumns << "\n";
    for (const Job& job : plan.jobs) out << job_row(job) << "\n";
  });
  return plan;
}

Plan load_plan(const fs::path& dir, regress::SuiteContext context) {
  const fs::path file = dir / kJobsFile;
  std::ifstream in(file);
  if (!in) throw_input_error(file.string(), "no sweep plan here (`slamkit sweep plan` writes it)");
  fs::path sweep_file;
  std::string hash;
  context.data_dir.reset();
  std::vector<std::string> rows;
  int line_number = 0, columns_line = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::vector<std::string> fields = split_tabs(line);
    if (fields.size() == 2 && fields[0] == "# sweep") {
      sweep_file = fields[1];
    } else if (fields.size() == 2 && fields[0] == "# sweep_hash") {
      hash = fields[1];
    } else if (fields.size() == 2 && fields[0] == "# data") {
      context.data_dir = fs::path(fields[1]);
    } else if (line == kColumns) {
      columns_line = line_number;
    } else if (columns_line == 0) {
      throw_input_error(file.string(), line_number, "not a sweep plan header line");
    } else {
      rows.push_back(line);
    }
  }
  if (sweep_file.empty() || hash.empty() || columns_line == 0)
    throw_input_error(file.string(), "not a sweep plan: the header is incomplete");
  if (path_kind(sweep_file) == PathKind::kMissing)
    throw_input_error(file.string(), 1, "the sweep file '" + sweep_file.string() + "' is gone");
  if (eval::fnv1a64_file(sweep_file) != hash)
    throw_input_error(file.string(), 2,
                      "the sweep file '" + sweep_file.string() +
                          "' changed since it was planned: plan again into a new folder");
  Plan plan;
  plan.dir = dir;
  plan.data_dir = context.data_dir;
  plan.sweep = load_sweep(sweep_file, context);
  expand(plan);
  // The suite or a settings file it names may have changed: the jobs must be the same ones.
  for (size_t i = 0; i < std::max(rows.size(), plan.jobs.size()); ++i)
    if (i >= rows.size() || i >= plan.jobs.size() || rows[i] != job_row(plan.jobs[i]))
      throw_input_error(file.string(), columns_line + 1 + int(i),
                        "the jobs differ from the sweep file's now: plan again into a new folder");
  return plan;
}

}  // namespace slamkit::sweep
