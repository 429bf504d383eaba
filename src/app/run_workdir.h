// The working directory of one `essaim run` (and of `essaim check`): a folder made for the
// run, holding a view of the experiment (output/run_files.h), which the process enters for
// the run and leaves after it. Relative reads of the scripts find the experiment's files
// there; relative writes land there, apart from every other run (docs/loop-functions.md).
#pragma once
#include <string>
#include <vector>

#include "output/run_files.h"

namespace essaim {

struct Model;

class RunWorkdir {
 public:
  RunWorkdir() = default;
  ~RunWorkdir() { Leave(); }
  RunWorkdir(const RunWorkdir&) = delete;
  RunWorkdir& operator=(const RunWorkdir&) = delete;

  /// Makes `folder` with the entries of the .argos file's folder, then those of the working
  /// directory not already there, and makes it the working directory. `exclude`: folders
  /// left out of the view (the output folder). A warning in `warning` when entries were
  /// left out past the limit.
  bool Enter(const std::string& folder, const std::string& argos_file, const std::vector<std::string>& exclude,
             std::string* warning, std::string* error);
  /// The view removed (the working directory stays); the files the run wrote or changed,
  /// each as `prefix` + its path in the folder.
  std::vector<std::string> Collect(const std::string& prefix);
  /// Back to the directory Enter left; the view removed if Collect did not run, and the
  /// folder too when the run wrote nothing there.
  void Leave();

 private:
  RunFilesView view_;
  std::string launch_;
};

/// A path of the .argos file that still names it from inside the run's working folder, whose
/// view holds the working directory's entries but not what lies above it: `../x.argos` made
/// absolute (the paths resolved beside it follow); any other path unchanged.
std::string NamedFromBelow(const std::string& file);
/// The same for the paths the run opens after it enters its folder (scripts, the library):
/// `../controllers/c.lua`, resolved beside an .argos file in the working directory, made
/// absolute; model.dir (the .argos file's folder, a root of `require` under --sandbox) too.
/// Call before RunWorkdir::Enter.
void AnchorPathsAbove(Model* model);

}  // namespace essaim
