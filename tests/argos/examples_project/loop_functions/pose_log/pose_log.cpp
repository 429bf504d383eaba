#include "pose_log.h"

#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <controllers/ground_forager/ground_forager.h>

void CPoseLog::Init(TConfigurationNode& t_tree) {
  std::string strFile = "poses.txt";
  GetNodeAttributeOrDefault(t_tree, "file", strFile, strFile);
  m_pFile = std::fopen(strFile.c_str(), "w");
  if (m_pFile == nullptr) THROW_ARGOSEXCEPTION("cannot write " << strFile);
}

void CPoseLog::PostStep() {
  CSpace::TMapPerType& tRobots = GetSpace().GetEntitiesByType("foot-bot");
  for (CSpace::TMapPerType::iterator it = tRobots.begin(); it != tRobots.end(); ++it) {
    CFootBotEntity& cRobot = *any_cast<CFootBotEntity*>(it->second);
    const SAnchor& sOrigin = cRobot.GetEmbodiedEntity().GetOriginAnchor();
    CRadians cZ, cY, cX;
    sOrigin.Orientation.ToEulerAngles(cZ, cY, cX);
    std::fprintf(m_pFile, "%u %s %a %a %a\n", GetSpace().GetSimulationClock(), cRobot.GetId().c_str(),
                 sOrigin.Position.GetX(), sOrigin.Position.GetY(), cZ.GetValue());
  }
}

void CPoseLog::PostExperiment() {
  UInt32 unCounted = 0;
  CSpace::TMapPerType& tRobots = GetSpace().GetEntitiesByType("foot-bot");
  for (CSpace::TMapPerType::iterator it = tRobots.begin(); it != tRobots.end(); ++it) {
    CFootBotEntity& cRobot = *any_cast<CFootBotEntity*>(it->second);
    CGroundForager* pcForager = dynamic_cast<CGroundForager*>(&cRobot.GetControllableEntity().GetController());
    if (pcForager != nullptr) unCounted += pcForager->GetFinds();
  }
  std::FILE* pFile = std::fopen("finds.txt", "w");
  if (pFile == nullptr) THROW_ARGOSEXCEPTION("cannot write finds.txt");
  std::fprintf(pFile, "reported %u counted %u\n", m_unReported.load(), unCounted);
  std::fclose(pFile);
}

void CPoseLog::Destroy() {
  if (m_pFile != nullptr) std::fclose(m_pFile);
  m_pFile = nullptr;
}

REGISTER_LOOP_FUNCTIONS(CPoseLog, "pose_log")
