#include "app/spec_checks.h"

#include <algorithm>
#include <filesystem>

#include "app/value_names.h"
#include "core/paths.h"
#include "core/strings.h"

namespace essaim {

namespace {
namespace fs = std::filesystem;

std::string At(const TestSpec& spec, int line) {
  return spec.file + (line > 0 ? ":" + std::to_string(line) : "") + ": ";
}

/// The .argos files of `folder`, each written as `prefix` + its name.
void ArgosFiles(const std::string& folder, const std::string& prefix, std::vector<std::string>* out) {
  std::error_code ec;
  for (fs::directory_iterator it(folder.empty() ? "." : folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".argos") out->push_back(prefix + it->path().filename().string());
}

/// The experiment as written in the spec (relative to its folder) and the closest .argos file
/// beside the spec or in the folder the path names.
std::string ExperimentHint(const TestSpec& spec, const std::string& written) {
  std::vector<std::string> candidates;
  const std::string spec_folder = DirName(spec.file);
  ArgosFiles(spec_folder, "", &candidates);
  const std::string written_folder = DirName(written);
  if (!written_folder.empty()) ArgosFiles(JoinPath(spec_folder, written_folder), written_folder + "/", &candidates);
  std::string hint = ClosestName(written, candidates);
  if (!hint.empty()) return "; did you mean '" + hint + "'?";
  if (candidates.empty()) return "";
  std::string list;
  for (size_t i = 0; i < candidates.size() && i < 5; ++i) list += (i ? ", " : "") + candidates[i];
  return " (.argos files there: " + list + ")";
}

/// `spec.experiment` is the written path joined to the spec's folder: take the folder off.
std::string Written(const TestSpec& spec) {
  const std::string folder = DirName(spec.file);
  if (folder.empty() || spec.experiment.rfind(folder + "/", 0) != 0) return spec.experiment;
  return spec.experiment.substr(folder.size() + 1);
}

/// The line of "FILE:LINE: ..." (0 when the message has none).
int LineOfError(const TestSpec& spec, const std::string& error) {
  if (error.rfind(spec.file + ":", 0) != 0) return 0;
  return static_cast<int>(ParseInt(Split(error.substr(spec.file.size() + 1), ':').front()).value_or(0));
}

void CheckPaths(const TestSpec& spec, std::vector<std::string>* errors) {
  if (!spec.experiment.empty() && !FileExists(spec.experiment))
    errors->push_back(At(spec, spec.experiment_line) + "experiment " + spec.experiment + " does not exist" +
                      ExperimentHint(spec, Written(spec)));
  if (!spec.workdir.empty() && !PathExists(spec.workdir))
    errors->push_back(At(spec, spec.workdir_line) + "workdir " + spec.workdir + " does not exist");
}
}  // namespace

void CheckSpec(const TestSpec& spec, std::vector<Expectation>* expectations, std::vector<std::string>* errors) {
  for (const SpecExpectation& written : spec.expectations) {
    Expectation e;
    std::string error;
    e.line = written.line;
    if (ParseExpectation(written.text, &e, &error))
      expectations->push_back(e);
    else
      errors->push_back(At(spec, written.line) + "expect \"" + written.text + "\": " + error);
  }
  CheckPaths(spec, errors);
  std::stable_sort(errors->begin(), errors->end(), [&](const std::string& a, const std::string& b) {
    return LineOfError(spec, a) < LineOfError(spec, b);  // in the order of the file
  });
}

std::string UnknownValueInSpec(const TestSpec& spec, const Expectation& e, const std::vector<SeedOutcome>& runs) {
  // Judged only when a run finished (else nothing tells a typo from a failure), on every run
  // that left its outputs: a value that a failed run wrote is no typo.
  std::vector<SeedOutcome> summarised;
  bool finished = false;
  for (const SeedOutcome& run : runs) {
    finished = finished || run.failure.empty();
    if (!run.summary.IsNull()) summarised.push_back(run);
  }
  std::string error = finished ? UnknownValueError(e.value, summarised) : "";
  return error.empty() ? "" : At(spec, e.line) + "expect \"" + e.text + "\": " + error;
}

}  // namespace essaim
