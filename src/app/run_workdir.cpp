#include "app/run_workdir.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/paths.h"
#include "model/model.h"

namespace essaim {

namespace fs = std::filesystem;

bool RunWorkdir::Enter(const std::string& folder, const std::string& argos_file,
                       const std::vector<std::string>& exclude, std::string* warning, std::string* error) {
  Leave();
  std::error_code ec;
  const std::string launch = fs::current_path(ec).string();
  if (ec) {
    *error = "cannot read the working directory: " + ec.message();
    return false;
  }
  const std::string argos_dir = DirName(argos_file).empty() ? launch : fs::absolute(DirName(argos_file), ec).string();
  std::vector<std::string> excluded;
  for (const std::string& e : exclude) excluded.push_back(CanonicalPath(e));
  if (!view_.Make(folder, {argos_dir, launch}, excluded, RunFilesLimits(), error)) return false;
  if (view_.LeftOut() > 0)
    *warning = std::to_string(view_.LeftOut()) + " entries of " + launch + " and " + argos_dir +
               " are not in the run's working folder (at most " + std::to_string(RunFilesLimits().max_entries) +
               "); start the run in a smaller folder";
  if (::chdir(folder.c_str()) != 0) {
    *error = "cannot enter the run's working folder " + folder + ": " + std::strerror(errno);
    view_.Finish();
    return false;
  }
  launch_ = launch;
  return true;
}

std::vector<std::string> RunWorkdir::Collect(const std::string& prefix) {
  std::vector<std::string> files = view_.Finish();
  for (std::string& f : files) f = prefix + f;
  return files;
}

std::string NamedFromBelow(const std::string& file) {
  const std::string normal = fs::path(file).lexically_normal().string();
  return normal.rfind("..", 0) == 0 ? fs::absolute(normal).lexically_normal().string() : file;
}

void AnchorPathsAbove(Model* model) {
  // require's roots under --sandbox: the folders the run's view links resolve to them.
  std::error_code ec;
  model->dir = fs::absolute(model->dir.empty() ? "." : model->dir, ec).lexically_normal().string();
  for (ControllerDef& c : model->controllers) c.script = NamedFromBelow(c.script);
  model->loop_functions.script = NamedFromBelow(model->loop_functions.script);
  model->loop_functions.library = NamedFromBelow(model->loop_functions.library);
}

void RunWorkdir::Leave() {
  view_.Finish();
  if (launch_.empty()) return;
  if (::chdir(launch_.c_str()) != 0) {
  }  // the launch directory is gone: nothing left to read there
  launch_.clear();
  std::error_code ec;
  if (fs::is_empty(view_.Folder(), ec) && !ec) fs::remove(view_.Folder(), ec);  // a run that wrote nothing
}

}  // namespace essaim
