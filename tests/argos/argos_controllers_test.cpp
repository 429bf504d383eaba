// C++ controllers through ArgosSession (argos_session.h), over a fake world and fake robot
// readings: the registry, the controller's id and hooks, GetSensor/GetActuator's answers and
// errors, error messages, LOG routed to each robot's log while two robots step on two
// threads, CSimulator from a controller, and CreateRNG's rule.
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/simulator/simulator.h>
#include <argos3/core/utility/logging/argos_log.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_light_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_motor_ground_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_proximity_default_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <map>
#include <thread>

#include "argos/argos_fakes.h"
#include "argos/argos_session.h"
#include "core/rng.h"

using namespace argos;
using essaim::ArgosControllerSpec;
using essaim::ArgosDeviceDecl;
using essaim::ArgosSession;

namespace {
class CProbe;
std::map<std::string, CProbe*> g_made;                       // by robot id, at Init
std::map<std::string, std::function<void(CProbe&)>> g_step;  // by robot id
std::map<std::string, std::function<void(CProbe&)>> g_init;  // by robot id
int g_deleted = 0;

class CProbe : public CCI_Controller {
 public:
  CProbe() : id_in_constructor(m_strId) {}
  ~CProbe() override { ++g_deleted; }
  void Init(TConfigurationNode& t_node) override {
    g_made[GetId()] = this;
    id_field = this->m_strId;
    std::string strFail;
    GetNodeAttributeOrDefault(t_node, "fail", strFail, std::string());
    if (strFail == "plain") THROW_ARGOSEXCEPTION("init failed on purpose");
    if (strFail == "nested") {
      try {
        THROW_ARGOSEXCEPTION("the cause");
      } catch (CARGoSException& ex) {
        THROW_ARGOSEXCEPTION_NESTED("the consequence", ex);
      }
    }
    if (strFail == "std") throw std::runtime_error("a std exception");
    if (g_init.count(GetId())) g_init[GetId()](*this);
  }
  void ControlStep() override {
    ++steps;
    auto it = g_step.find(GetId());
    if (it != g_step.end()) it->second(*this);
  }
  void Reset() override { ++resets; }
  void Destroy() override {
    ++destroys;
    RLOG << "destroyed" << std::endl;
  }

  std::string id_in_constructor, id_field;
  int steps = 0, resets = 0, destroys = 0;
  std::vector<UInt64> seeds;
};
}  // namespace

REGISTER_CONTROLLER(CProbe, "probe_controller")

namespace {
std::string ProbeLibrary() {
  for (const essaim::ArgosRegistration& r : essaim::ArgosRegisteredControllers())
    if (r.label == "probe_controller") return r.library;
  return "";
}

class ArgosControllers : public ::testing::Test {
 protected:
  void SetUp() override {
    g_made.clear(), g_step.clear(), g_init.clear();
    g_deleted = 0;
  }
  bool Create(uint32_t robot, std::vector<ArgosDeviceDecl> devices = {}) {
    ArgosControllerSpec spec{"probe_controller", "ctl", "test.argos:7: <probe_controller id=\"ctl\">", devices};
    return session.CreateController(robot, "fb" + std::to_string(robot), {ProbeLibrary()}, spec, &io[robot], &error);
  }
  bool Init(uint32_t robot, const std::string& fail = "") {
    ticpp::Element params("params");
    if (!fail.empty()) params.SetAttribute("fail", fail);
    return session.InitController(robot, params, &error);
  }
  CProbe& Made(uint32_t robot) { return *g_made.at("fb" + std::to_string(robot)); }

  essaim::FakeWorld world;
  ArgosSession session{&world};
  essaim::FakeRobotIo io[3];
  std::string error;
};
}  // namespace

TEST_F(ArgosControllers, RegistrationNamesTheLibraryAndTheApiVersion) {
  bool found = false;
  for (const essaim::ArgosRegistration& r : essaim::ArgosRegisteredControllers())
    if (r.label == "probe_controller") {
      found = true;
      EXPECT_EQ(r.api_version, ARGOS_ESSAIM_API_VERSION);
      EXPECT_NE(r.library.find("essaim_tests"), std::string::npos) << r.library;
    }
  EXPECT_TRUE(found);
}

TEST_F(ArgosControllers, AnUnknownLabelOrLibraryIsRefused) {
  ArgosControllerSpec spec{"no_such_controller", "ctl", "test.argos:7", {}};
  EXPECT_FALSE(session.CreateController(0, "fb0", {ProbeLibrary()}, spec, &io[0], &error));
  EXPECT_NE(error.find("no controllers registered as 'no_such_controller' (REGISTER_CONTROLLER)"), std::string::npos)
      << error;
  EXPECT_NE(error.find("probe_controller"), std::string::npos) << error;  // what the library registers
  spec.label = "probe_controller";
  EXPECT_FALSE(session.CreateController(0, "fb0", {"/nowhere/libother.so"}, spec, &io[0], &error));
  EXPECT_NE(error.find("registers it, but"), std::string::npos) << error;
}

TEST_F(ArgosControllers, AControllerBuiltForAnotherApiVersionIsRefused) {
  RegisterController(
      "old_probe", []() -> CCI_Controller* { return new CProbe; }, ARGOS_ESSAIM_API_VERSION - 1);
  ArgosControllerSpec spec{"old_probe", "ctl", "test.argos:7", {}};
  EXPECT_FALSE(session.CreateController(0, "fb0", {ProbeLibrary()}, spec, &io[0], &error));
  EXPECT_NE(error.find("controller 'old_probe' was built for essaim's ARGoS API version 3, this essaim provides "
                       "version 4: rebuild the library against this essaim"),
            std::string::npos)
      << error;
}

TEST_F(ArgosControllers, TheIdIsTheRobotsFromInitOnAndTheHooksRun) {
  ASSERT_TRUE(Create(0)) << error;
  ASSERT_TRUE(Init(0)) << error;
  CProbe& probe = Made(0);
  EXPECT_EQ(probe.id_in_constructor, "");  // ARGoS sets it after the constructor
  EXPECT_EQ(probe.GetId(), "fb0");
  EXPECT_EQ(probe.id_field, "fb0");
  ASSERT_TRUE(session.StepController(0, &error)) << error;
  ASSERT_TRUE(session.StepController(0, &error)) << error;
  EXPECT_EQ(probe.steps, 2);
  ASSERT_TRUE(session.ResetController(0, &error)) << error;
  ASSERT_TRUE(session.DestroyController(0, &error)) << error;
  EXPECT_EQ(probe.resets, 1);
  EXPECT_EQ(probe.destroys, 1);
  EXPECT_EQ(session.ControllerLog(0), "O[fb0] destroyed\n");
  session.DeleteController(0);
  EXPECT_EQ(g_deleted, 1);
  EXPECT_FALSE(session.StepController(0, &error));
  EXPECT_NE(error.find("no C++ controller"), std::string::npos) << error;
}

TEST_F(ArgosControllers, GetSensorAndGetActuatorFindWhatIsDeclared) {
  ASSERT_TRUE(Create(0, {{"footbot_motor_ground", "rot_z_only", true},
                         {"footbot_proximity", "default", true},
                         {"differential_steering", "default", false}}))
      << error;
  g_init["fb0"] = [](CProbe& c) {
    EXPECT_NE(c.GetSensor<CCI_FootBotMotorGroundSensor>("footbot_motor_ground"), nullptr);
    EXPECT_NE(c.GetSensor<CFootBotMotorGroundRotZOnlySensor>("footbot_motor_ground"), nullptr);
    EXPECT_NE(c.GetActuator<CCI_DifferentialSteeringActuator>("differential_steering"), nullptr);
    EXPECT_TRUE(c.HasSensor("footbot_proximity"));
    EXPECT_FALSE(c.HasSensor("footbot_light"));
    EXPECT_TRUE(c.HasActuator("differential_steering"));
    EXPECT_EQ(c.GetAllSensors().size(), 2u);
    EXPECT_EQ(c.GetAllActuators().size(), 1u);
  };
  ASSERT_TRUE(Init(0)) << error;
}

TEST_F(ArgosControllers, AMissingDeviceNamesItAndTheControllersElement) {
  ASSERT_TRUE(Create(0, {{"footbot_proximity", "default", true}})) << error;
  g_init["fb0"] = [](CProbe& c) { c.GetSensor<CCI_FootBotLightSensor>("footbot_light"); };
  ASSERT_FALSE(Init(0));
  EXPECT_EQ(error.find("robot fb0: controller 'ctl' (Init): Unknown sensor type footbot_light requested in controller "
                       "(test.argos:7: <probe_controller id=\"ctl\">)"),
            0u)
      << error;
  ASSERT_TRUE(Create(1)) << error;
  g_init["fb1"] = [](CProbe& c) { c.GetActuator<CCI_DifferentialSteeringActuator>("differential_steering"); };
  ASSERT_FALSE(Init(1));
  EXPECT_NE(error.find("Unknown actuator type differential_steering"), std::string::npos) << error;
}

// The proximity sensor (default) is not the rot_z_only motor ground class; the light
// interface is not the motor ground's.
TEST_F(ArgosControllers, AnotherClassThanTheImplementationMadeThrows) {
  ASSERT_TRUE(Create(0, {{"footbot_proximity", "default", true}, {"footbot_motor_ground", "rot_z_only", true}}))
      << error;
  g_init["fb0"] = [](CProbe& c) {
    EXPECT_THROW(c.GetSensor<CFootBotMotorGroundRotZOnlySensor>("footbot_proximity"), CARGoSException);
    EXPECT_NO_THROW(c.GetSensor<CFootBotProximityDefaultSensor>("footbot_proximity"));
    c.GetSensor<CCI_FootBotLightSensor>("footbot_motor_ground");
  };
  ASSERT_FALSE(Init(0));
  EXPECT_NE(error.find("Sensor type footbot_motor_ground (test.argos:7: <probe_controller id=\"ctl\">) cannot be cast "
                       "to type argos::CCI_FootBotLightSensor: its implementation made a "
                       "argos::CFootBotMotorGroundRotZOnlySensor"),
            std::string::npos)
      << error;
}

TEST_F(ArgosControllers, ADeviceEssaimHasNoClassForFailsCreation) {
  EXPECT_FALSE(Create(0, {{"footbot_motor_ground", "default", true}}));
  EXPECT_NE(error.find("robot fb0: controller 'ctl' (constructor): test.argos:7: <probe_controller id=\"ctl\">: "
                       "essaim has no sensor <footbot_motor_ground implementation=\"default\">"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("footbot_motor_ground (rot_z_only)"), std::string::npos) << error;  // what it has
  EXPECT_TRUE(session.LastErrorIsConfiguration());                                         // a bad .argos element
  EXPECT_EQ(g_deleted, 1);  // the controller made is deleted
  EXPECT_FALSE(session.StepController(0, &error));
}

TEST_F(ArgosControllers, AnExceptionNamesTheRobotTheHookTheFileAndTheLine) {
  ASSERT_TRUE(Create(0)) << error;
  ASSERT_FALSE(Init(0, "plain"));
  EXPECT_EQ(error.find("robot fb0: controller 'ctl' (Init): "), 0u) << error;
  EXPECT_NE(error.find("argos_controllers_test.cpp:"), std::string::npos) << error;
  EXPECT_NE(error.find(": init failed on purpose"), std::string::npos) << error;
  ASSERT_FALSE(Init(0, "nested"));
  EXPECT_NE(error.find("the consequence\n[NESTED] the cause"), std::string::npos) << error;
  ASSERT_FALSE(Init(0, "std"));
  EXPECT_EQ(error, "robot fb0: controller 'ctl' (Init): a std exception");
  g_step["fb0"] = [](CProbe& c) { c.GetActuator<CCI_DifferentialSteeringActuator>("differential_steering"); };
  EXPECT_FALSE(session.StepController(0, &error));
  EXPECT_EQ(error.find("robot fb0: controller 'ctl' (ControlStep): "), 0u) << error;
}

TEST_F(ArgosControllers, AWheelVelocityThatIsNotFiniteStopsTheRobotWithAnError) {
  ASSERT_TRUE(Create(0, {{"differential_steering", "default", false}})) << error;
  ASSERT_TRUE(Init(0)) << error;
  g_step["fb0"] = [](CProbe& c) {
    c.GetActuator<CCI_DifferentialSteeringActuator>("differential_steering")->SetLinearVelocity(5, NAN);
  };
  EXPECT_FALSE(session.StepController(0, &error));
  EXPECT_NE(error.find("robot fb0: controller 'ctl' (ControlStep): "), std::string::npos) << error;
  EXPECT_NE(error.find("actuators.cpp:"), std::string::npos) << error;
  EXPECT_NE(error.find("SetLinearVelocity(5, nan)"), std::string::npos) << error;
}

// Each robot's lines go to its own log, whole and in order, while both step at once.
TEST_F(ArgosControllers, LogLinesGoToTheRobotWhoseControllerWroteThemOnAnyThread) {
  for (uint32_t r = 0; r < 2; ++r) {
    ASSERT_TRUE(Create(r)) << error;
    ASSERT_TRUE(Init(r)) << error;
    g_step["fb" + std::to_string(r)] = [](CProbe& c) {
      LOG << "robot " << c.GetId() << " step ";
      LOG << c.steps << std::endl;
      LOGERR << "err " << c.GetId() << std::endl;
    };
  }
  const int kSteps = 200;
  std::string errors[2];
  auto run = [&](uint32_t r) {
    for (int k = 0; k < kSteps; ++k)
      if (!session.StepController(r, &errors[r])) return;
  };
  std::thread first(run, 0), second(run, 1);
  first.join(), second.join();
  for (uint32_t r = 0; r < 2; ++r) {
    EXPECT_EQ(errors[r], "");
    std::string expected;
    const std::string id = "fb" + std::to_string(r);
    for (int k = 1; k <= kSteps; ++k) expected += "Orobot " + id + " step " + std::to_string(k) + "\nEerr " + id + "\n";
    EXPECT_EQ(session.ControllerLog(r), expected);
  }
  EXPECT_TRUE(world.log.empty());
  EXPECT_EQ(session.ControllerLog(7), "");  // no controller, no lines
}

// Loop functions (or another robot's controller) reach the C++ controller itself through the
// robot's entity, and cast it to its class.
TEST_F(ArgosControllers, TheRobotsEntityGivesItsCppController) {
  world.robots = {"fb0"};
  ASSERT_TRUE(Create(0)) << error;
  g_init["fb0"] = [](CProbe& c) {
    CSpace::TMapPerType& robots = CSimulator::GetInstance().GetSpace().GetEntitiesByType("foot-bot");
    CFootBotEntity* robot = any_cast<CFootBotEntity*>(robots.at("fb0"));
    EXPECT_EQ(dynamic_cast<CProbe*>(&robot->GetControllableEntity().GetController()), &c);
  };
  ASSERT_TRUE(Init(0)) << error;
}

// The space's maps are made by the first lookup of a stage, under a lock while robots step at once.
TEST_F(ArgosControllers, RobotsSteppingAtOnceLookUpTheSpace) {
  world.robots = {"fb0", "fb1"};
  for (uint32_t r = 0; r < 2; ++r) {
    ASSERT_TRUE(Create(r)) << error;
    ASSERT_TRUE(Init(r)) << error;
    g_step["fb" + std::to_string(r)] = [](CProbe& c) {
      CSpace& space = CSimulator::GetInstance().GetSpace();
      CFootBotEntity* robot = any_cast<CFootBotEntity*>(space.GetEntitiesByType("foot-bot").at(c.GetId()));
      EXPECT_EQ(&robot->GetControllableEntity().GetController(), &c);
      EXPECT_EQ(space.GetEntity(c.GetId()).GetId(), c.GetId());
    };
  }
  std::string errors[2];
  std::thread first([&] { session.StepController(0, &errors[0]); });
  std::thread second([&] { session.StepController(1, &errors[1]); });
  first.join(), second.join();
  EXPECT_EQ(errors[0] + errors[1], "");
}

TEST_F(ArgosControllers, AControllerReachesTheSimulator) {
  world.seed = 99, world.tick = 5;
  ASSERT_TRUE(Create(0)) << error;
  g_init["fb0"] = [](CProbe&) {
    EXPECT_EQ(CSimulator::GetInstance().GetRandomSeed(), 99u);
    EXPECT_EQ(CSimulator::GetInstance().GetSpace().GetSimulationClock(), 5u);
    // Any id, as a Release ARGoS: the tick is the world's (0.1 s).
    EXPECT_EQ(CSimulator::GetInstance().GetPhysicsEngine("no_such_engine").GetSimulationClockTick(), 0.1);
    EXPECT_EQ(CPhysicsEngine::GetInverseSimulationClockTick(), 10);
    EXPECT_EQ(CSimulator::GetInstance().GetPhysicsEngines().size(), 1u);
    CSimulator::GetInstance().GetLoopFunctions();  // the experiment has none
  };
  ASSERT_FALSE(Init(0));
  EXPECT_NE(error.find("GetLoopFunctions: the experiment has no C++ loop functions"), std::string::npos) << error;
}

// Made in Init (serially, in robot order), generators take the "argos" category's draws as
// ARGoS's do; made in ControlStep, each robot's take its own seeder's, whatever the threads.
TEST_F(ArgosControllers, CreateRngFollowsArgosSeriallyAndEachRobotsSeederInSteps) {
  world.seed = 12345;
  ArgosSession fresh(&world);
  CRandom::CRNG seeder(12345);
  const CRange<UInt32> kSeedRange(1, std::numeric_limits<UInt32>::max());
  for (uint32_t r = 0; r < 2; ++r) {
    ArgosControllerSpec spec{"probe_controller", "ctl", "test.argos:7", {}};
    ASSERT_TRUE(fresh.CreateController(r, "fb" + std::to_string(r), {ProbeLibrary()}, spec, &io[r], &error));
    g_init["fb" + std::to_string(r)] = [](CProbe& c) { c.seeds.push_back(CRandom::CreateRNG("argos")->GetSeed()); };
    ticpp::Element params("params");
    ASSERT_TRUE(fresh.InitController(r, params, &error)) << error;
    EXPECT_EQ(Made(r).seeds.at(0), seeder.Uniform(kSeedRange));
    g_step["fb" + std::to_string(r)] = [](CProbe& c) { c.seeds.push_back(CRandom::CreateRNG("argos")->GetSeed()); };
  }
  // Robot 1 steps first, on another thread: its seeds are still its own.
  std::thread([&] { ASSERT_TRUE(fresh.StepController(1, &error)); }).join();
  ASSERT_TRUE(fresh.StepController(0, &error)) << error;
  ASSERT_TRUE(fresh.StepController(1, &error)) << error;
  for (uint32_t r = 0; r < 2; ++r) {
    CRandom::CRNG own(static_cast<UInt32>(essaim::DeriveSeed(12345, essaim::StreamKind::Controller, r)));
    const UInt64 first = own.Uniform(kSeedRange);
    EXPECT_EQ(Made(r).seeds.at(1), first);
  }
  EXPECT_EQ(Made(1).seeds.size(), 3u);
  EXPECT_NE(Made(1).seeds[2], Made(1).seeds[1]);
  // The category's next draw is untouched by the steps.
  g_init["fb2"] = [](CProbe& c) { c.seeds.push_back(CRandom::CreateRNG("argos")->GetSeed()); };
  ArgosControllerSpec spec{"probe_controller", "ctl", "test.argos:7", {}};
  ASSERT_TRUE(fresh.CreateController(2, "fb2", {ProbeLibrary()}, spec, &io[2], &error));
  ticpp::Element params("params");
  ASSERT_TRUE(fresh.InitController(2, params, &error)) << error;
  EXPECT_EQ(Made(2).seeds.at(0), seeder.Uniform(kSeedRange));
}

TEST_F(ArgosControllers, CategoriesCannotChangeDuringAStep) {
  ASSERT_TRUE(Create(0)) << error;
  ASSERT_TRUE(Init(0)) << error;
  g_step["fb0"] = [](CProbe&) { CRandom::CreateCategory("mine", 3); };
  EXPECT_FALSE(session.StepController(0, &error));
  EXPECT_NE(error.find("CRandom::CreateCategory: not from ControlStep"), std::string::npos) << error;
}
