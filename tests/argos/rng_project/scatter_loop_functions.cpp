// Scatters robots at random: the draws come from CRandom over CRange, reached through
// loop_functions.h as in ARGoS (no rng.h or range.h included here). Robots are added with the
// foot-bot constructor of three ARGoS eras and placed where they fit; every draw and every
// robot's place is written to a file.
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>

#include <fstream>

using namespace argos;

class CScatterLoopFunctions : public CLoopFunctions {
 public:
  void Init(TConfigurationNode& t_tree) override {
    std::string strOutput;
    GetNodeAttribute(GetNode(t_tree, "params"), "output", strOutput);
    m_cOutput.open(strOutput.c_str(), std::ios::out | std::ios::trunc);
    m_pcRNG = CRandom::CreateRNG("argos");
    const CVector3 cHome(0, 0, 0);
    // ARGoS 3.0.0-beta18 to beta34: the camera's aperture after the RAB range.
    Place(new CFootBotEntity("early", "walker", cHome, CQuaternion(), 2.0, ToRadians(CDegrees(70.0))));
    // ARGoS 3.0.0-beta35 to beta48: the RAB data size, then the cameras.
    Place(new CFootBotEntity("middle", "walker", cHome, CQuaternion(), 2.5, 20, ToRadians(CDegrees(70.0)), true,
                             ToRadians(CDegrees(30.0)), 0.035, 2.0));
    // ARGoS 3.0.0-beta49 and later: a battery model between them.
    Place(new CFootBotEntity("late", "walker", cHome, CQuaternion(), 3.0, 10, "", ToRadians(CDegrees(70.0))));
    CRange<UInt32> cDice(1, 7);
    for (int i = 0; i < 5; ++i) m_cOutput << "die\t" << m_pcRNG->Uniform(cDice) << "\n";
  }

  void PostExperiment() override {
    CSpace::TMapPerType& tRobots = GetSpace().GetEntitiesByType("foot-bot");
    m_cOutput << "robots\t" << tRobots.size() << "\n";
    m_cOutput.close();
  }

 private:
  // Added at home, then moved to random places in the arena's left half until one is free.
  void Place(CFootBotEntity* pc_robot) {
    AddEntity(*pc_robot);
    const CRange<Real> cX(-1.5, -0.2), cY(-1.5, 1.5);
    for (UInt32 unTrial = 0; unTrial < 100; ++unTrial) {
      const CVector3 cPosition(m_pcRNG->Uniform(cX), m_pcRNG->Uniform(cY), 0);
      const CQuaternion cOrientation(m_pcRNG->Uniform(CRadians::UNSIGNED_RANGE), CVector3::Z);
      if (MoveEntity(pc_robot->GetEmbodiedEntity(), cPosition, cOrientation)) {
        const CVector3& cAt = pc_robot->GetEmbodiedEntity().GetOriginAnchor().Position;
        m_cOutput << "robot\t" << pc_robot->GetId() << "\t" << cAt.GetX() << "\t" << cAt.GetY() << "\t"
                  << (cX.WithinMinBoundIncludedMaxBoundIncluded(cAt.GetX()) ? "in" : "out") << "\n";
        return;
      }
    }
    THROW_ARGOSEXCEPTION("no room for " << pc_robot->GetId());
  }

  std::ofstream m_cOutput;
  CRandom::CRNG* m_pcRNG = nullptr;
};

REGISTER_LOOP_FUNCTIONS(CScatterLoopFunctions, "scatter_loop_functions")
