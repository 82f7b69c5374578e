#include "eval/regression/baseline.h"

#include <sys/utsname.h>

#include <cmath>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/error.h"
#include "eval/regression/process.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string trimmed(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  return s;
}

// "CPU, N cores, Linux release" -> "CPU, N cores".
std::string hardware(const std::string& machine) {
  const size_t cores = machine.find(" cores");
  return cores == std::string::npos ? machine : machine.substr(0, cores);
}

}  // namespace

std::optional<Baseline> read_baseline(const fs::path& file) {
  if (!fs::exists(file)) return std::nullopt;
  std::ifstream in(file);
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::exception& e) {
    throw_input_error(file.string(), std::string("not valid JSON: ") + e.what());
  }
  if (doc.is_object() && doc.contains("format") && doc["format"] != kBaselineFormat)
    throw_input_error(file.string(), "baseline format " + doc["format"].dump().substr(0, 40) +
                                         " is not supported (this slamkit reads format " +
                                         std::to_string(kBaselineFormat) +
                                         "; write it again with --update-baselines)");
  if (!doc.is_object() || !doc.contains("metrics") || !doc["metrics"].is_object())
    throw_input_error(file.string(), "no \"metrics\" object (write it with --update-baselines)");
  Baseline b;
  const auto text = [&](const char* key) {
    return doc.contains(key) && doc[key].is_string() ? doc[key].get<std::string>() : "";
  };
  b.provenance = {text("version"), text("settings_hash"), text("machine"), text("date")};
  b.sequence = text("sequence");
  for (const auto& [key, value] : doc["metrics"].items()) {
    if (!find_metric(key)) continue;  // a metric since retired stays readable
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      throw_input_error(file.string(), "metrics." + key + " is not a finite number");
    b.metrics[key] = value.get<double>();
  }
  return b;
}

void write_baseline(const fs::path& file, const Baseline& b) {
  json doc;
  doc["format"] = kBaselineFormat;
  doc["version"] = b.provenance.version;
  doc["settings_hash"] = b.provenance.settings_hash;
  doc["machine"] = b.provenance.machine;
  doc["date"] = b.provenance.date;
  doc["sequence"] = b.sequence;
  doc["metrics"] = json::object();
  for (const auto& [key, value] : b.metrics) doc["metrics"][key] = value;
  fs::create_directories(file.parent_path());
  const fs::path temp = file.string() + ".tmp";
  {
    std::ofstream out(temp);
    out << doc.dump(2) << "\n";
    if (!out) throw_input_error(temp.string(), "cannot write file");
  }
  fs::rename(temp, file);
}

std::string slamkit_version() {
  const auto described = capture_output(
      "git", {"-C", SLAMKIT_SOURCE_DIR, "describe", "--always", "--dirty", "--tags"});
  return described ? trimmed(*described) : std::string("slamkit-") + SLAMKIT_RELEASE;
}

std::string machine_description() {
  std::string cpu = "unknown CPU";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      cpu = trimmed(line.substr(line.find(':') + 2));
      break;
    }
  std::string text = cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
  utsname name{};
  if (uname(&name) == 0) text += std::string(", ") + name.sysname + " " + name.release;
  return text;
}

bool same_machine(const std::string& a, const std::string& b) {
  return !a.empty() && hardware(a) == hardware(b);
}

}  // namespace slamkit::regress
