#ifndef COURSE_LOOP_FUNCTIONS_H
#define COURSE_LOOP_FUNCTIONS_H

#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <argos3/plugins/simulator/entities/cylinder_entity.h>

#include <fstream>

using namespace argos;

class CCourseLoopFunctions : public CLoopFunctions {
 public:
  void Init(TConfigurationNode& t_tree) override;
  void Reset() override;
  void Destroy() override;
  void PreStep() override;
  void PostStep() override;
  bool IsExperimentFinished() override;
  void PostExperiment() override;
  CColor GetFloorColor(const CVector2& c_position_on_plane) override;

 private:
  Real ReadRobotNumber(CFootBotEntity& c_robot, const char* str_field);
  void PlaceRobots();
  std::string m_strOutput;
  std::ofstream m_cOutput;
  CRandom::CRNG* m_pcRNG = nullptr;
  Real m_fNestRadius = 0.5;
  bool m_bAllBlack = false;
  UInt32 m_unFlipTick = 10;
  UInt32 m_unStopTick = 30;
  UInt32 m_unCylinders = 3;
  UInt32 m_unRobots = 0;
  UInt32 m_unMoves = 0, m_unMovesRefused = 0;
};

#endif
