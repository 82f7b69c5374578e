// slamkit.ate, rpe, evaluate, align, associate: `slamkit eval ate|rpe|all` in-process. Each
// builds the CLI's EvaluationRequest from keyword options named as the CLI's (--max-diff is
// max_diff) and calls the same eval::run_evaluation, so the metrics dict is metrics.json's and
// files written with out= are the CLI's, byte for byte.
#include <pybind11/stl.h>

#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>

#include "bin/output_folder.h"
#include "bin/python/bindings.h"
#include "bin/python/option_values.h"
#include "bin/python/trajectory_arrays.h"
#include "eval/evaluation_run.h"

namespace slamkit::python {
namespace {

namespace py = pybind11;
using namespace pybind11::literals;
using eval::EvaluationRequest;

enum Options { kCommon = 1, kAte = 2, kRpe = 4 };

double non_negative(const py::handle& value, const char* option) {
  const double v = value.cast<double>();
  if (!(v >= 0))
    throw std::invalid_argument(std::string(option) + ": " + std::to_string(v) +
                                " is not a non-negative number");
  return v;
}

using Setter = std::function<void(EvaluationRequest&, const py::handle&)>;
struct Option {
  int group;
  Setter set;
};

// Every keyword option, with the CLI option it stands for and the same checks.
const std::map<std::string, Option>& option_table() {
  static const std::map<std::string, Option> table = {
      {"convention",
       {kCommon,
        [](auto& a, auto v) {
          a.convention = member(v, "convention", {"tum", "evo"});
        }}},
      {"max_diff", {kCommon, [](auto& a, auto v) { a.max_diff = non_negative(v, "max_diff"); }}},
      {"offset", {kCommon, [](auto& a, auto v) { a.offset = v.template cast<double>(); }}},
      {"association",
       {kCommon,
        [](auto& a, auto v) {
          a.association = member(v, "association", {"tum", "evo"});
        }}},
      {"duplicate_stamps",
       {kCommon,
        [](auto& a, auto v) {
          a.duplicates = member(v, "duplicate_stamps", {"last", "first", "all"});
        }}},
      {"time_unit",
       {kCommon,
        [](auto& a, auto v) {
          a.time_unit = member(v, "time_unit", {"s", "us", "ns"});
        }}},
      {"format",
       {kCommon,
        [](auto& a, auto v) {
          a.format = member(v, "format", {"tum", "kitti", "euroc"});
        }}},
      {"gt_format",
       {kCommon,
        [](auto& a, auto v) {
          a.gt_format = member(v, "gt_format", {"tum", "kitti", "euroc"});
        }}},
      {"est_format",
       {kCommon,
        [](auto& a, auto v) {
          a.est_format = member(v, "est_format", {"tum", "kitti", "euroc"});
        }}},
      {"times", {kCommon, [](auto& a, auto v) { a.kitti_times = text(v); }}},
      {"out", {kCommon, [](auto& a, auto v) { a.out_dir = text(v); }}},
      {"json", {kCommon, [](auto& a, auto v) { a.json_path = text(v); }}},
      {"plot", {kCommon, [](auto& a, auto v) { a.plot_dir = text(v); }}},
      {"no_plot", {kCommon, [](auto& a, auto v) { a.no_plot = v.template cast<bool>(); }}},
      {"pdf", {kCommon, [](auto& a, auto v) { a.figures.pdf = v.template cast<bool>(); }}},
      {"plot_format", {kCommon, [](auto& a, auto v) { a.figures.formats = plot_formats(v); }}},
      {"dpi", {kCommon, [](auto& a, auto v) { a.figures.dpi = dpi(v); }}},
      {"title", {kCommon, [](auto& a, auto v) { a.title = text(v); }}},
      {"system_name", {kCommon, [](auto& a, auto v) { a.system_name = text(v); }}},
      {"quiet", {kCommon, [](auto& a, auto v) { a.quiet = v.template cast<bool>(); }}},
      {"align",
       {kAte | kRpe,
        [](auto& a, auto v) {
          a.align = member(v, "align", {"se3", "sim3", "translation", "none"});
        }}},
      {"align_first", {kAte, [](auto& a, auto v) { a.align_first = v.template cast<size_t>(); }}},
      {"aligned", {kAte, [](auto& a, auto v) { a.aligned_path = text(v); }}},
      {"planes",
       {kAte,
        [](auto& a, auto v) {
          a.planes = text(v);
          for (const std::string& plane : eval::split_planes(a.planes))
            if (plane != "xy" && plane != "xz" && plane != "yz")
              throw std::invalid_argument("planes: unknown plane '" + plane +
                                          "' (use xy, xz or yz)");
        }}},
      {"delta", {kRpe, [](auto& a, auto v) { a.rpe.delta = v.template cast<double>(); }}},
      {"unit",
       {kRpe,
        [](auto& a, auto v) {
          a.unit = member(v, "unit", {"s", "f", "m", "deg", "rad"});
        }}},
      {"all_pairs", {kRpe, [](auto& a, auto v) { a.rpe.all_pairs = v.template cast<bool>(); }}},
      {"rpe_convention",
       {kRpe,
        [](auto& a, auto v) {
          a.rpe_convention = member(v, "rpe_convention", {"tum", "evo"});
        }}},
      {"delta_tol",
       {kRpe, [](auto& a, auto v) { a.rpe.rel_delta_tol = non_negative(v, "delta_tol"); }}},
  };
  return table;
}

// A path names the file in messages and metrics.json as on the command line; a Trajectory is
// used as it is and named `name`.
void set_input(const py::handle& given, const char* name, std::string& label,
               std::shared_ptr<const TrajectoryFile>& data) {
  if (py::isinstance<TrajectoryFile>(given)) {
    label = name;
    data = given.cast<std::shared_ptr<TrajectoryFile>>();
  } else {
    label = text(given);
  }
}

EvaluationRequest make_request(const py::handle& gt, const py::handle& est, const py::kwargs& kw,
                               int groups, const char* function) {
  EvaluationRequest a;
  a.quiet = true;                        // a library prints nothing unless asked (quiet=False)
  if (groups == kRpe) a.align = "none";  // `eval rpe`'s default
  set_input(gt, "groundtruth", a.gt, a.gt_data);
  set_input(est, "estimate", a.est, a.est_data);
  for (const auto& [key, value] : kw) {
    const std::string name = key.cast<std::string>();
    if (name == "csv" && groups != kCommon) continue;  // errors.csv or rpe.csv: below
    const auto found = option_table().find(name);
    if (found == option_table().end() || !(found->second.group & (groups | kCommon)))
      throw std::invalid_argument(std::string(function) + "() has no option '" + name + "'");
    found->second.set(a, value);
  }
  if (kw.contains("csv")) (groups == kRpe ? a.rpe_csv : a.ate_csv) = text(kw["csv"]);
  if (!a.out_dir.empty()) cli::check_output_folder("--out", a.out_dir);
  if (!a.plot_dir.empty()) cli::check_output_folder("--plot", a.plot_dir);
  return a;
}

py::object json_to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

Array vector_array(const std::vector<double>& v) {
  Array a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

Array points_array(const std::vector<Eigen::Vector3d>& v) {
  Array a({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  for (size_t i = 0; i < v.size(); ++i)
    Eigen::Map<Eigen::Vector3d>(a.mutable_data() + 3 * i) = v[i];
  return a;
}

py::object ate_arrays(const eval::AteResult& ate) {
  return py::module_::import("types").attr("SimpleNamespace")(
      "stamps"_a = vector_array(ate.stamps), "trans_errors"_a = vector_array(ate.trans_errors),
      "rot_errors_deg"_a = vector_array(ate.rot_errors_deg),
      "est_positions"_a = points_array(ate.est_aligned),
      "gt_positions"_a = points_array(ate.gt_positions));
}

py::object rpe_arrays(const eval::RpeResult& rpe) {
  std::vector<double> columns[6];
  for (auto& c : columns) c.reserve(rpe.pairs.size());
  for (const eval::RpePair& p : rpe.pairs) {
    columns[0].push_back(p.stamp_est_i);
    columns[1].push_back(p.stamp_est_j);
    columns[2].push_back(p.stamp_gt_i);
    columns[3].push_back(p.stamp_gt_j);
    columns[4].push_back(p.trans);
    columns[5].push_back(p.rot_deg);
  }
  return py::module_::import("types").attr("SimpleNamespace")(
      "stamps_i"_a = vector_array(columns[0]), "stamps_j"_a = vector_array(columns[1]),
      "gt_stamps_i"_a = vector_array(columns[2]), "gt_stamps_j"_a = vector_array(columns[3]),
      "trans_errors"_a = vector_array(columns[4]), "rot_errors_deg"_a = vector_array(columns[5]));
}

// Runs the evaluation without the GIL; plots asked for with plot= and not drawn raise
// RuntimeError, as the CLI exits 1.
eval::EvaluationResult evaluate(EvaluationRequest& a, bool do_ate, bool do_rpe) {
  eval::EvaluationResult result;
  bool drawn;
  {
    py::gil_scoped_release release;
    drawn = eval::run_evaluation(a, do_ate, do_rpe, &result);
  }
  if (!drawn) throw std::runtime_error("plots asked for with plot= were not drawn (see stderr)");
  return result;
}

py::object evaluation_object(const eval::EvaluationResult& r) {
  return py::module_::import("types").attr("SimpleNamespace")(
      "metrics"_a = json_to_python(r.metrics), "ate"_a = r.ate ? ate_arrays(*r.ate) : py::none(),
      "rpe"_a = r.rpe ? rpe_arrays(*r.rpe) : py::none());
}

}  // namespace

void bind_evaluation(py::module_& m) {
  m.def(
      "ate",
      [](const py::object& gt, const py::object& est, const py::kwargs& kw) {
        EvaluationRequest a = make_request(gt, est, kw, kAte, "ate");
        return evaluation_object(evaluate(a, true, false));
      },
      "groundtruth"_a, "estimate"_a,
      "`slamkit eval ate`: the absolute trajectory error of `estimate` (a path or a Trajectory) "
      "against `groundtruth`. Keyword options as the CLI's (max_diff=, align=, out=, ...). Returns "
      "an object with .metrics (metrics.json as a dict) and .ate (per-pose arrays).");
  m.def(
      "rpe",
      [](const py::object& gt, const py::object& est, const py::kwargs& kw) {
        EvaluationRequest a = make_request(gt, est, kw, kRpe, "rpe");
        return evaluation_object(evaluate(a, false, true));
      },
      "groundtruth"_a, "estimate"_a,
      "`slamkit eval rpe`: the relative pose error. Returns .metrics and .rpe (per-pair arrays).");
  m.def(
      "evaluate",
      [](const py::object& gt, const py::object& est, const py::kwargs& kw) {
        EvaluationRequest a = make_request(gt, est, kw, kAte | kRpe, "evaluate");
        return evaluation_object(evaluate(a, true, true));
      },
      "groundtruth"_a, "estimate"_a,
      "`slamkit eval all`: ATE and RPE from one reading. Returns .metrics, .ate and .rpe.");
  m.def(
      "align",
      [](const py::object& gt, const py::object& est, const py::kwargs& kw) {
        EvaluationRequest a = make_request(gt, est, kw, kAte, "align");
        const eval::EvaluationResult r = evaluate(a, true, false);
        auto aligned = std::make_shared<TrajectoryFile>();
        aligned->trajectory = eval::apply_alignment(r.est->trajectory, r.ate->alignment);
        return py::make_tuple(aligned, json_to_python(r.metrics["ate"]["alignment"]));
      },
      "groundtruth"_a, "estimate"_a,
      "The whole estimate moved by the ATE alignment (aligned.txt of `slamkit eval ate`), and "
      "the alignment (metrics.json's ate.alignment). Options as ate()'s.");
  m.def(
      "associate",
      [](const py::object& gt, const py::object& est, const py::kwargs& kw) {
        EvaluationRequest a = make_request(gt, est, kw, kCommon, "associate");
        std::vector<IndexPair> pairs;
        {
          py::gil_scoped_release release;
          pairs = eval::associate_inputs(a);
        }
        py::array_t<long long> out({static_cast<py::ssize_t>(pairs.size()), py::ssize_t{2}});
        for (size_t k = 0; k < pairs.size(); ++k) {
          out.mutable_data()[2 * k] = static_cast<long long>(pairs[k].first);
          out.mutable_data()[2 * k + 1] = static_cast<long long>(pairs[k].second);
        }
        return out;
      },
      "groundtruth"_a, "estimate"_a,
      "The (groundtruth index, estimate index) pairs `slamkit eval` measures, as an (N, 2) "
      "array; indices into the trajectories as read with the same time_unit and duplicate "
      "rule. Options: convention, association, max_diff, offset, duplicate_stamps, time_unit.");
}

}  // namespace slamkit::python
