/* Loop functions as a 2013 project wrote them for ARGoS 3.0.0-beta17: the space and the
   simulator are the base class's m_cSpace and m_cSimulator, a body is a positional entity
   (GetPosition, GetOrientation, GetInitPosition), MoveEntity takes b_check_only and says
   whether the body fits. Every tick they write each robot's pose and the light's position;
   a static post, placed with SetPosition before AddEntity, is told another place later. */
#ifndef LEGACY_LOOP_FUNCTIONS_H
#define LEGACY_LOOP_FUNCTIONS_H

#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <argos3/plugins/simulator/entities/cylinder_entity.h>
#include <argos3/plugins/simulator/entities/light_entity.h>

#include <fstream>

using namespace argos;

class CLegacyLoopFunctions : public CLoopFunctions {
 public:
  virtual void Init(TConfigurationNode& t_tree);
  virtual void PostStep();
  virtual void Destroy();

 private:
  void PlaceLastRobot();
  void AddPost();
  void ReportPost();
  void WriteRows();

  std::ofstream m_cOutput;
  CCylinderEntity* m_pcPost;
  UInt32 m_unNudgeTick;
  CRandom::CRNG* m_pcRNG;
};

#endif
