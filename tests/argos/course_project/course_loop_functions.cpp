#include "course_loop_functions.h"

#include <argos3/core/simulator/simulator.h>
#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/wrappers/lua/lua_controller.h>
#include <argos3/plugins/simulator/entities/light_entity.h>
#include <argos3/plugins/simulator/media/led_medium.h>

void CCourseLoopFunctions::Init(TConfigurationNode& t_tree) {
  TConfigurationNode& tParams = GetNode(t_tree, "params");
  GetNodeAttribute(tParams, "output", m_strOutput);
  GetNodeAttribute(tParams, "nest_radius", m_fNestRadius);
  GetNodeAttribute(tParams, "flip_tick", m_unFlipTick);
  GetNodeAttributeOrDefault(tParams, "stop_tick", m_unStopTick, m_unStopTick);
  GetNodeAttribute(tParams, "cylinders", m_unCylinders);
  GetNodeAttributeOrDefault(tParams, "robots", m_unRobots, m_unRobots);
  m_cOutput.open(m_strOutput.c_str(), std::ios_base::trunc | std::ios_base::out);
  m_cOutput << "# tick\trobot\tsteps\tground" << std::endl;
  m_pcRNG = CRandom::CreateRNG("argos");
  CLEDMedium& cLEDs = CSimulator::GetInstance().GetMedium<CLEDMedium>("leds");
  for (UInt32 i = 0; i < m_unCylinders; ++i) {
    CVector3 cPos(m_pcRNG->Uniform(CRange<Real>(1.0, 1.5)), m_pcRNG->Uniform(CRange<Real>(-1.5, 1.5)), 0);
    CQuaternion cOrient;
    cOrient.FromEulerAngles(m_pcRNG->Uniform(CRadians::UNSIGNED_RANGE), CRadians::ZERO, CRadians::ZERO);
    CCylinderEntity* pcCylinder = new CCylinderEntity("object" + ToString(i), cPos, cOrient, true, 0.05, 0.1, 0.2);
    pcCylinder->GetLEDEquippedEntity().AddLED(CVector3(0, 0, 0.1), CColor::RED);
    AddEntity(*pcCylinder);
    pcCylinder->GetLEDEquippedEntity().AddToMedium(cLEDs);
  }
  CLightEntity* pcLight = new CLightEntity("beacon", CVector3(-1.5, 1.5, 0.5), CColor::YELLOW, 3.0);
  pcLight->AddToMedium(cLEDs);
  AddEntity(*pcLight);
  PlaceRobots();
  LOG << "course: " << GetSpace().GetEntitiesByType("cylinder").size() << " objects placed" << std::endl;
}

/* The students' robots, placed as ARGoS's custom distribution example does: added at the
   origin, then moved to random places until one is free. */
void CCourseLoopFunctions::PlaceRobots() {
  for (UInt32 i = 0; i < m_unRobots; ++i) {
    CFootBotEntity* pcFB = new CFootBotEntity("student" + ToString(i), "student");
    AddEntity(*pcFB);
    UInt32 unTrials = 0;
    bool bDone = false;
    do {
      CVector3 cPos(m_pcRNG->Uniform(CRange<Real>(-1.5, -0.5)), m_pcRNG->Uniform(CRange<Real>(-1.5, 1.5)), 0);
      CQuaternion cOrient;
      cOrient.FromEulerAngles(m_pcRNG->Uniform(CRadians::UNSIGNED_RANGE), CRadians::ZERO, CRadians::ZERO);
      bDone = MoveEntity(pcFB->GetEmbodiedEntity(), cPos, cOrient);
    } while (!bDone && ++unTrials < 100);
    if (!bDone) THROW_ARGOSEXCEPTION("Can't place robot " << pcFB->GetId());
  }
  LOG << "course: " << GetSpace().GetEntitiesByType("foot-bot").size() << " robots" << std::endl;
}

void CCourseLoopFunctions::Reset() { m_cOutput.close(); }

void CCourseLoopFunctions::Destroy() { m_cOutput.close(); }

CColor CCourseLoopFunctions::GetFloorColor(const CVector2& c_position_on_plane) {
  if (m_bAllBlack || c_position_on_plane.Length() < m_fNestRadius) return CColor::BLACK;
  return CColor::WHITE;
}

Real CCourseLoopFunctions::ReadRobotNumber(CFootBotEntity& c_robot, const char* str_field) {
  CLuaController& cController = dynamic_cast<CLuaController&>(c_robot.GetControllableEntity().GetController());
  lua_State* ptState = cController.GetLuaState();
  lua_getglobal(ptState, str_field);
  Real fValue = lua_isnumber(ptState, -1) ? lua_tonumber(ptState, -1) : -1;
  lua_pop(ptState, 1);
  return fValue;
}

void CCourseLoopFunctions::PreStep() {
  UInt32 unClock = GetSpace().GetSimulationClock();
  if (unClock == m_unFlipTick) {
    m_bAllBlack = true;
    GetSpace().GetFloorEntity().SetChanged();
  }
  if (unClock % 5 != 0) return;
  CSpace::TMapPerType& cCylinders = GetSpace().GetEntitiesByType("cylinder");
  for (CSpace::TMapPerType::iterator it = cCylinders.begin(); it != cCylinders.end(); ++it) {
    CCylinderEntity& cCylinder = *any_cast<CCylinderEntity*>(it->second);
    CVector3 cTarget(m_pcRNG->Uniform(CRange<Real>(-1.5, 1.5)), m_pcRNG->Uniform(CRange<Real>(-1.5, 1.5)), 0);
    if (MoveEntity(cCylinder.GetEmbodiedEntity(), cTarget, cCylinder.GetEmbodiedEntity().GetOriginAnchor().Orientation))
      ++m_unMoves;
    else
      ++m_unMovesRefused;
  }
}

void CCourseLoopFunctions::PostStep() {
  CSpace::TMapPerType& cFootBots = GetSpace().GetEntitiesByType("foot-bot");
  for (CSpace::TMapPerType::iterator it = cFootBots.begin(); it != cFootBots.end(); ++it) {
    CFootBotEntity& cFootBot = *any_cast<CFootBotEntity*>(it->second);
    m_cOutput << GetSpace().GetSimulationClock() << "\t" << cFootBot.GetId() << "\t"
              << ReadRobotNumber(cFootBot, "steps") << "\t" << ReadRobotNumber(cFootBot, "ground") << std::endl;
  }
}

bool CCourseLoopFunctions::IsExperimentFinished() { return GetSpace().GetSimulationClock() >= m_unStopTick; }

void CCourseLoopFunctions::PostExperiment() {
  CSpace::TMapPerType& cCylinders = GetSpace().GetEntitiesByType("cylinder");
  m_cOutput << "# finished at " << GetSpace().GetSimulationClock() << " objects " << cCylinders.size() << " moves "
            << m_unMoves << " refused " << m_unMovesRefused << std::endl;
  LOG << "course: done" << std::endl;
}

REGISTER_LOOP_FUNCTIONS(CCourseLoopFunctions, "course_loop_functions")
