// The run folder's bookkeeping (output/out_folder, output/atomic_file, TimeseriesCsv): which
// names are essaim's, what is moved aside, what an output may replace. The CLI's behaviour
// around them is tested in tests/app/test_cli_outputs.py.
#include "output/out_folder.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/paths.h"
#include "output/atomic_file.h"
#include "output/summary.h"
#include "support/scene.h"

namespace essaim {
namespace {

namespace fs = std::filesystem;
using namespace essaim::testing;

TEST(OutFolder, KnowsTheNamesEssaimWritesAndNoOthers) {
  for (const char* name : {"summary.json", "metrics.json", "timeseries.csv", "recording.bin", "replay.html",
                           "snapshot-120.png", "summary.json.tmp.4242", "recording.bin.tmp.1"})
    EXPECT_TRUE(IsRunOutputName(name)) << name;
  for (const char* name : {"notes.txt", "summary.json.bak", "summary.json.tmp.", "summary.json.tmp.12a",
                           "snapshot-1.jpg", "my-summary.json", "previous", "stdout.txt", "sweep-run.json"})
    EXPECT_FALSE(IsRunOutputName(name)) << name;
}

TEST(OutFolder, MovesOnlyEssaimsFilesAndKeepsEveryEarlierRun) {
  TempDir d;
  d.Write("summary.json", "3");
  d.Write("recording.bin", "3");
  d.Write("notes.txt", "mine");
  fs::create_directories(d.path() + "/previous");
  d.Write("previous/summary.json", "2");
  d.Write("previous/timeseries.csv", "2");
  d.Write("previous/keep.txt", "mine too");
  fs::create_directories(d.path() + "/previous-2");
  d.Write("previous-2/summary.json", "1");
  std::vector<std::string> moved;
  std::string error;
  ASSERT_TRUE(SetAsideEarlierOutputs(d.path(), &moved, &error)) << error;
  EXPECT_EQ(moved, (std::vector<std::string>{"recording.bin", "summary.json"}));
  std::string text;
  EXPECT_TRUE(ReadFile(d.path() + "/previous/summary.json", &text) && text == "3");
  EXPECT_FALSE(FileExists(d.path() + "/previous/timeseries.csv"));
  // The older runs moved one generation back, whole.
  EXPECT_TRUE(ReadFile(d.path() + "/previous-2/summary.json", &text) && text == "2");
  EXPECT_TRUE(ReadFile(d.path() + "/previous-2/timeseries.csv", &text) && text == "2");
  EXPECT_TRUE(FileExists(d.path() + "/previous-2/keep.txt"));
  EXPECT_TRUE(ReadFile(d.path() + "/previous-3/summary.json", &text) && text == "1");
  EXPECT_TRUE(FileExists(d.path() + "/notes.txt"));
  EXPECT_FALSE(FileExists(d.path() + "/summary.json"));
  ASSERT_TRUE(SetAsideEarlierOutputs(d.path(), &moved, &error)) << error;
  EXPECT_TRUE(moved.empty());
  EXPECT_FALSE(fs::exists(d.path() + "/previous-4"));  // nothing to set aside: no shift
}

TEST(OutFolder, ASecondLockOnAFolderIsRefusedWithTheOwnersPid) {
  TempDir d;
  OutFolderLock first, second;
  std::string error;
  ASSERT_TRUE(first.Acquire(d.path(), &error)) << error;
  // flock locks are per open file: a second open in this process conflicts like another's.
  EXPECT_FALSE(second.Acquire(d.path(), &error));
  EXPECT_NE(error.find("is in use by another essaim run (pid " + std::to_string(::getpid()) + ")"), std::string::npos)
      << error;
  first.Release();
  EXPECT_FALSE(fs::exists(d.path() + "/" + kLockFile));
  EXPECT_TRUE(second.Acquire(d.path(), &error)) << error;
}

TEST(OutFolder, RefusesAFileAndAFolderNamedLikeAnOutput) {
  TempDir d;
  std::string error;
  EXPECT_FALSE(PrepareOutFolder(d.Write("file", "x"), &error));
  EXPECT_NE(error.find("is a file, not a folder"), std::string::npos) << error;
  EXPECT_TRUE(PrepareOutFolder(d.path() + "/a/b", &error)) << error;
  EXPECT_TRUE(fs::is_directory(d.path() + "/a/b"));
  EXPECT_TRUE(fs::is_empty(d.path() + "/a/b"));  // the probe is gone
  fs::create_directories(d.path() + "/a/b/metrics.json");
  EXPECT_FALSE(PrepareOutFolder(d.path() + "/a/b", &error));
  EXPECT_NE(error.find("metrics.json is not a regular file"), std::string::npos) << error;
}

TEST(AtomicFile, ReplacesRegularFilesAndWritesThroughSymlinksOnly) {
  TempDir d;
  std::string error, text;
  std::string fifo = d.path() + "/fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_FALSE(WriteFileAtomic(fifo, "x", &error));
  EXPECT_NE(error.find("it is a FIFO, not a regular file"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_FALSE(WriteFileAtomic(d.path(), "x", &error));
  EXPECT_NE(error.find("it is a folder"), std::string::npos) << error;
  std::string real = d.Write("real", "old"), link = d.path() + "/link";
  fs::create_symlink(real, link);
  ASSERT_TRUE(WriteFileAtomic(link, "new", &error)) << error;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(ReadFile(real, &text) && text == "new");
}

TEST(TimeseriesCsv, QuotesNamesAsRfc4180AndSpellsNonFiniteValues) {
  Timeseries ts;
  ts.columns = {"plain", "a,b", "say \"hi\"", "two\nlines"};
  ts.rows = {{1.5, NAN, INFINITY, -INFINITY}};
  EXPECT_EQ(TimeseriesCsv(ts), "plain,\"a,b\",\"say \"\"hi\"\"\",\"two\nlines\"\n1.5,NaN,Inf,-Inf\n");
}

}  // namespace
}  // namespace essaim
