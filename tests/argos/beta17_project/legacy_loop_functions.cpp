#include "legacy_loop_functions.h"

#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/utility/logging/argos_log.h>

#include <iomanip>

void CLegacyLoopFunctions::Init(TConfigurationNode& t_tree) {
  TConfigurationNode& tParams = GetNode(t_tree, "params");
  std::string strOutput;
  GetNodeAttribute(tParams, "output", strOutput);
  GetNodeAttribute(tParams, "nudge_tick", m_unNudgeTick);
  m_cOutput.open(strOutput.c_str(), std::ios::out | std::ios::trunc);
  m_cOutput << std::setprecision(12);
  m_pcRNG = CRandom::CreateRNG("argos", "mt19937");
  LOG << "legacy: " << m_pcRNG->GetType() << ", seed " << m_cSimulator.GetRandomSeed() << ", clock "
      << m_cSpace.GetSimulationClock() << std::endl;
  PlaceLastRobot();
  AddPost();
  /* The beacon goes to the far corner: a light is a positional entity too */
  CLightEntity& cLight = *any_cast<CLightEntity*>(m_cSpace.GetEntitiesByType("light")["beacon"]);
  MoveEntity(cLight, CVector3(1.5, 1.5, 0.5), CQuaternion(), false);
  WriteRows();
}

/* fb3 goes where there is room, checked first; the place of fb0 is refused */
void CLegacyLoopFunctions::PlaceLastRobot() {
  CSpace::TMapPerType& tRobots = m_cSpace.GetEntitiesByType("foot-bot");
  CEmbodiedEntity& cBody = any_cast<CFootBotEntity*>(tRobots["fb3"])->GetEmbodiedEntity();
  CEmbodiedEntity& cFirst = any_cast<CFootBotEntity*>(tRobots["fb0"])->GetEmbodiedEntity();
  CQuaternion cOrient;
  cOrient.FromAngleAxis(CRadians::PI_OVER_TWO, CVector3::Z);
  bool bFits = MoveEntity(cBody, CVector3(-1.0, 1.0, 0), cOrient, true);
  if (bFits) {
    MoveEntity(cBody, CVector3(-1.0, 1.0, 0), cOrient, false);
  }
  bool bOnFirst = MoveEntity(cBody, cFirst.GetPosition(), cFirst.GetOrientation(), false);
  LOG << "legacy: fb3 fits " << (bFits ? "yes" : "no") << ", onto fb0 " << (bOnFirst ? "moved" : "refused")
      << std::endl;
}

void CLegacyLoopFunctions::WriteRows() {
  UInt32 unClock = m_cSpace.GetSimulationClock();
  CSpace::TMapPerType& tRobots = m_cSpace.GetEntitiesByType("foot-bot");
  for (CSpace::TMapPerType::iterator it = tRobots.begin(); it != tRobots.end(); ++it) {
    CEmbodiedEntity& cBody = any_cast<CFootBotEntity*>(it->second)->GetEmbodiedEntity();
    CRadians cZ, cY, cX, cInitZ;
    cBody.GetOrientation().ToEulerAngles(cZ, cY, cX);
    cBody.GetInitOrientation().ToEulerAngles(cInitZ, cY, cX);
    m_cOutput << unClock << "\t" << it->first << "\t" << cBody.GetPosition().GetX() << "\t"
              << cBody.GetPosition().GetY() << "\t" << cZ.GetValue() << "\t" << cBody.GetInitPosition().GetX() << "\t"
              << cBody.GetInitPosition().GetY() << "\t" << cInitZ.GetValue() << std::endl;
  }
  CLightEntity& cLight = *any_cast<CLightEntity*>(m_cSpace.GetEntitiesByType("light")["beacon"]);
  m_cOutput << unClock << "\tbeacon\t" << cLight.GetPosition().GetX() << "\t" << cLight.GetPosition().GetY()
            << std::endl;
}

/* A static post, made at the origin and told where to stand before it is added */
void CLegacyLoopFunctions::AddPost() {
  m_pcPost = new CCylinderEntity("post", CVector3(), CQuaternion(), false, 0.1, 0.2);
  m_pcPost->GetEmbodiedEntity().SetPosition(CVector3(0.0, -1.6, 0.0));
  AddEntity(*m_pcPost);
  LOG << "legacy: post added at " << m_pcPost->GetEmbodiedEntity().GetPosition().GetX() << ","
      << m_pcPost->GetEmbodiedEntity().GetPosition().GetY() << std::endl;
}

/* Told another place, the static post reports it for good, but the physics never moved it */
void CLegacyLoopFunctions::ReportPost() {
  const CVector3& cStands = m_pcPost->GetEmbodiedEntity().GetOriginAnchor().Position;
  LOG << "legacy: post reports " << m_pcPost->GetEmbodiedEntity().GetPosition().GetX() << ","
      << m_pcPost->GetEmbodiedEntity().GetPosition().GetY() << ", stands at " << cStands.GetX() << "," << cStands.GetY()
      << std::endl;
}

/* At the nudge tick, fb0's body is told another pose: it reports it until the physics
   updates it, but does not move */
void CLegacyLoopFunctions::PostStep() {
  WriteRows();
  if (m_cSpace.GetSimulationClock() == m_unNudgeTick + 3) ReportPost();
  if (m_cSpace.GetSimulationClock() != m_unNudgeTick) return;
  m_pcPost->GetEmbodiedEntity().SetPosition(CVector3(1.2, 1.6, 0.0));
  CFootBotEntity& cFB = *any_cast<CFootBotEntity*>(m_cSpace.GetEntitiesByType("foot-bot")["fb0"]);
  cFB.GetEmbodiedEntity().SetPosition(CVector3(9.0, 9.0, 0.0));
  cFB.GetEmbodiedEntity().SetOrientation(CQuaternion(CRadians::PI, CVector3::Z));
  CRadians cZ, cY, cX;
  cFB.GetEmbodiedEntity().GetOrientation().ToEulerAngles(cZ, cY, cX);
  LOG << "legacy: fb0 reports " << cFB.GetEmbodiedEntity().GetPosition().GetX() << ","
      << cFB.GetEmbodiedEntity().GetPosition().GetY() << " heading " << ToDegrees(cZ).GetValue() << " after SetPosition"
      << std::endl;
}

void CLegacyLoopFunctions::Destroy() { m_cOutput.close(); }

REGISTER_LOOP_FUNCTIONS(CLegacyLoopFunctions, "legacy_loop_functions")
