/* One library, several controllers (census: several per file), each failing its own way. */
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/simulator/simulator.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/logging/argos_log.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_light_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>

using namespace argos;

/* Drives; robot `victim` throws at tick `tick`. */
class CThrower : public CCI_Controller {
 public:
  void Init(TConfigurationNode& t_node) override {
    m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
    GetNodeAttribute(t_node, "victim", m_strVictim);
    GetNodeAttribute(t_node, "tick", m_unTick);
  }
  void ControlStep() override {
    if (GetId() == m_strVictim && CSimulator::GetInstance().GetSpace().GetSimulationClock() == m_unTick)
      THROW_ARGOSEXCEPTION("the thrower gives up at tick " << m_unTick);
    m_pcWheels->SetLinearVelocity(5, 5);
  }

 private:
  CCI_DifferentialSteeringActuator* m_pcWheels = nullptr;
  std::string m_strVictim;
  UInt32 m_unTick = 0;
};
REGISTER_CONTROLLER(CThrower, "thrower_controller")

/* Asks for a sensor its entry does not declare. */
class CUndeclared : public CCI_Controller {
 public:
  void Init(TConfigurationNode&) override { GetSensor<CCI_FootBotLightSensor>("footbot_light"); }
};
REGISTER_CONTROLLER(CUndeclared, "undeclared_controller")

/* Robot `victim` dereferences a null pointer at tick `tick`. */
class CCrasher : public CCI_Controller {
 public:
  void Init(TConfigurationNode& t_node) override {
    GetNodeAttribute(t_node, "victim", m_strVictim);
    GetNodeAttribute(t_node, "tick", m_unTick);
  }
  void ControlStep() override {
    if (GetId() == m_strVictim && ++m_unSteps == m_unTick) {
      volatile int* pnNull = nullptr;
      *pnNull = 1;
    }
  }

 private:
  std::string m_strVictim;
  UInt32 m_unTick = 0, m_unSteps = 0;
};
REGISTER_CONTROLLER(CCrasher, "crasher_controller")

/* Wanders on random draws (one RNG made in Init, one in the first ControlStep) and logs. */
class CRandomWalker : public CCI_Controller {
 public:
  void Init(TConfigurationNode&) override {
    m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
    m_pcRNG = CRandom::CreateRNG("argos");
    LOG << GetId() << " first draw " << m_pcRNG->Uniform(CRange<UInt32>(0, 1000)) << std::endl;
  }
  void ControlStep() override {
    if (m_pcLateRNG == nullptr) m_pcLateRNG = CRandom::CreateRNG("argos");
    const Real fLeft = m_pcRNG->Uniform(CRange<Real>(0, 10));
    const Real fRight = m_pcLateRNG->Gaussian(2, 5);
    if (m_pcRNG->Bernoulli(0.01)) LOG << GetId() << " turns " << fLeft << " " << fRight << std::endl;
    m_pcWheels->SetLinearVelocity(fLeft, fRight);
  }

 private:
  CCI_DifferentialSteeringActuator* m_pcWheels = nullptr;
  CRandom::CRNG* m_pcRNG = nullptr;
  CRandom::CRNG* m_pcLateRNG = nullptr;
};
REGISTER_CONTROLLER(CRandomWalker, "random_walker_controller")

/* Loop functions that add two robots running the walker in Init (census: loop functions that
 * create their robots), and check in PostExperiment that both were stepped. */
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>

class CSpawner : public CLoopFunctions {
 public:
  void Init(TConfigurationNode&) override {
    for (UInt32 i = 0; i < 2; ++i) {
      CFootBotEntity* pcRobot =
          new CFootBotEntity("spawned" + std::to_string(i), "walker", CVector3(-2.0 + i, 2.0, 0), CQuaternion());
      AddEntity(*pcRobot);
    }
  }
  void PostExperiment() override {
    CSpace::TMapPerType& tRobots = GetSpace().GetEntitiesByType("foot-bot");
    for (CSpace::TMapPerType::iterator it = tRobots.begin(); it != tRobots.end(); ++it) {
      CFootBotEntity& cRobot = *any_cast<CFootBotEntity*>(it->second);
      CRandomWalker* pcWalker = dynamic_cast<CRandomWalker*>(&cRobot.GetControllableEntity().GetController());
      LOG << cRobot.GetId() << (pcWalker ? " walks" : " does not walk") << std::endl;
    }
  }
};
REGISTER_LOOP_FUNCTIONS(CSpawner, "spawner")
