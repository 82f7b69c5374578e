#include "eval/association.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/enum_names.h"
#include "core/error.h"

namespace slamkit::eval {

std::vector<IndexPair> associate(const Trajectory& gt, const Trajectory& est,
                                 const AssociationOptions& options) {
  std::vector<IndexPair> pairs;
  if (options.method == AssociationMethod::kTum) {
    pairs = associate_greedy(gt.stamps(), est.stamps(), options.max_diff, options.offset);
  } else {
    for (size_t i = 0; i < est.size(); ++i)
      if (const auto g = gt.nearest(est[i].stamp + options.offset, options.max_diff))
        pairs.push_back({*g, i});
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const IndexPair& a, const IndexPair& b) { return a.second < b.second; });
  return pairs;
}

void require_enough_pairs(size_t pair_count, const Trajectory& gt, const Trajectory& est,
                          const std::string& gt_name, const std::string& est_name,
                          const AssociationOptions& options) {
  if (pair_count >= 2) return;
  char text[1024];
  std::snprintf(text, sizeof text,
                "only %zu estimated pose(s) matched groundtruth within %g s (offset %g s, %s "
                "association); groundtruth %s has %zu poses over %.6f .. %.6f, estimate %s "
                "has %zu poses over %.6f .. %.6f; are these the right files (or is a time "
                "offset needed)?",
                pair_count, options.max_diff, options.offset, to_string(options.method).c_str(),
                gt_name.c_str(), gt.size(), gt.start_time(), gt.end_time(), est_name.c_str(),
                est.size(), est.start_time(), est.end_time());
  throw_input_error(est_name, text);
}

namespace {
constexpr EnumNames<AssociationMethod, 2> kAssociationNames = {
    {{AssociationMethod::kTum, "tum"}, {AssociationMethod::kEvo, "evo"}}};
}  // namespace

std::string to_string(AssociationMethod method) { return name_of(kAssociationNames, method); }

AssociationMethod parse_association_method(const std::string& text) {
  if (const auto method = value_named(kAssociationNames, text)) return *method;
  throw std::invalid_argument("unknown association '" + text + "' (use " +
                              choices(kAssociationNames) + ")");
}

}  // namespace slamkit::eval
