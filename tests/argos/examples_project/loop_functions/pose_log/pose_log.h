/* Loop functions that write every foot-bot's pose after each step, exactly (hexadecimal
 * floats), so that two runs' trajectories compare bit for bit; the board the foragers report
 * their finds to; and, at the end, the finds counted by reaching into each C++ forager. */
#ifndef POSE_LOG_H
#define POSE_LOG_H

#include <argos3/core/simulator/loop_functions.h>
#include <controllers/ground_forager/find_board.h>

#include <atomic>
#include <cstdio>

using namespace argos;

class CPoseLog : public CLoopFunctions, public CFindBoard {
 public:
  virtual void Init(TConfigurationNode& t_tree);
  virtual void PostStep();
  virtual void PostExperiment();
  virtual void Destroy();
  virtual void ReportFind() { ++m_unReported; }

 private:
  std::FILE* m_pFile = nullptr;
  std::atomic<UInt32> m_unReported{0};
};

#endif
