// The run's working folder (output/run_files): what the view places, what it leaves after the
// run, and that the originals are never written through a copy. The CLI's use of it is tested
// in tests/app/test_run_files.py.
#include "output/run_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/paths.h"
#include "support/scene.h"

namespace essaim {
namespace {

namespace fs = std::filesystem;
using namespace essaim::testing;

std::string Read(const std::string& path) {
  std::string text;
  ReadFile(path, &text);
  return text;
}

TEST(RunFiles, PlacesTheExperimentFirstThenTheLaunchFolderAndKeepsOnlyWhatTheRunWrote) {
  TempDir experiment, launch, out;
  experiment.Write("a.lua", "experiment's");
  experiment.Write("results.txt", "earlier results");
  fs::create_directories(experiment.path() + "/data");
  experiment.Write("data/zones.txt", "1 2 3");
  launch.Write("a.lua", "launch folder's");
  launch.Write("only_here.txt", "x");
  RunFilesView view;
  const std::string folder = out.path() + "/files";
  std::string error;
  ASSERT_TRUE(view.Make(folder, {experiment.path(), launch.path()}, {}, RunFilesLimits(), &error)) << error;
  EXPECT_EQ(Read(folder + "/a.lua"), "experiment's");
  EXPECT_EQ(Read(folder + "/only_here.txt"), "x");
  EXPECT_EQ(Read(folder + "/data/zones.txt"), "1 2 3");  // a folder, linked
  EXPECT_TRUE(fs::is_symlink(folder + "/data"));
  EXPECT_FALSE(fs::is_symlink(folder + "/results.txt"));  // a small file, copied

  std::ofstream(folder + "/results.txt") << "this run's";  // overwrites its copy only
  std::ofstream(folder + "/new.csv") << "a,b\n1,2\n";
  fs::create_directories(folder + "/made");
  std::ofstream(folder + "/made/x.txt") << "x";
  const std::vector<std::string> kept = view.Finish();
  EXPECT_EQ(kept, (std::vector<std::string>{"made/x.txt", "new.csv", "results.txt"}));
  EXPECT_EQ(Read(experiment.path() + "/results.txt"), "earlier results");
  EXPECT_TRUE(fs::exists(experiment.path() + "/data/zones.txt"));  // a link removed, not its target
  EXPECT_TRUE(view.Finish().empty());                              // once only
}

TEST(RunFiles, LinksLargeFilesAndBoundsTheEntries) {
  TempDir source, out;
  for (int i = 0; i < 5; ++i) source.Write("f" + std::to_string(i), std::string(100, 'x'));
  RunFilesLimits limits;
  limits.max_entries = 3;
  limits.copy_max_bytes = 50;  // every file "large": linked
  RunFilesView view;
  std::string error;
  ASSERT_TRUE(view.Make(out.path() + "/files", {source.path()}, {}, limits, &error)) << error;
  EXPECT_EQ(view.LeftOut(), 2u);
  EXPECT_TRUE(fs::is_symlink(out.path() + "/files/f0"));
  EXPECT_FALSE(fs::exists(out.path() + "/files/f4"));
  EXPECT_TRUE(view.Finish().empty());
}

TEST(RunFiles, LeavesOutTheExcludedFolderAndRefusesAFolderInUse) {
  TempDir source, other;
  fs::create_directories(source.path() + "/out");
  source.Write("a.txt", "a");
  RunFilesView view;
  std::string error;
  ASSERT_TRUE(view.Make(source.path() + "/out/files", {source.path()}, {CanonicalPath(source.path() + "/out")},
                        RunFilesLimits(), &error))
      << error;
  EXPECT_FALSE(fs::exists(source.path() + "/out/files/out"));
  EXPECT_TRUE(fs::exists(source.path() + "/out/files/a.txt"));
  view.Finish();
  fs::create_directories(other.path() + "/files");
  other.Write("files/left.txt", "an earlier run's");
  RunFilesView second;
  EXPECT_FALSE(second.Make(other.path() + "/files", {source.path()}, {}, RunFilesLimits(), &error));
  EXPECT_NE(error.find("not empty"), std::string::npos) << error;
}

}  // namespace
}  // namespace essaim
