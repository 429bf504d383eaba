// Every hook and call of the census, each result written as "key value" to the file the
// XML names; tests/argos/test_cpp_loop_functions.py checks the lines.
#include <argos3/core/simulator/entity/floor_entity.h>
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/simulator/simulator.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/utility/math/angles.h>
#include <argos3/core/utility/math/range.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/core/wrappers/lua/lua_controller.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <argos3/plugins/simulator/entities/box_entity.h>
#include <argos3/plugins/simulator/entities/cylinder_entity.h>
#include <argos3/plugins/simulator/entities/led_entity.h>
#include <argos3/plugins/simulator/entities/light_entity.h>
#include <argos3/plugins/simulator/media/led_medium.h>

#include <fstream>

using namespace argos;

class CCensusLoopFunctions : public CLoopFunctions {
 public:
  void Init(TConfigurationNode& t_tree) override {
    ReadConfiguration(t_tree);
    ReadSpace();
    DrawNumbers();
    AddAndRemove();
    MoveAndColour();
    CQuaternion cTurn;
    cTurn.FromAngleAxis(CRadians::PI_OVER_TWO, CVector3::Z);
    CRadians cZ, cY, cX;
    cTurn.ToEulerAngles(cZ, cY, cX);
    Record("quaternion_yaw", cZ.GetValue());
    Record("seed", GetSimulator().GetRandomSeed());
    Record("max_clock", GetSimulator().GetMaxSimulationClock());
    LOGERR << "census: an error line" << std::endl;
  }
  void PreStep() override {
    if (GetSpace().GetSimulationClock() != 1) return;
    CFootBotEntity& cRobot = *any_cast<CFootBotEntity*>(GetSpace().GetEntitiesByType("foot-bot")["fb0"]);
    lua_State* L = dynamic_cast<CLuaController&>(cRobot.GetControllableEntity().GetController()).GetLuaState();
    lua_getglobal(L, "counter");
    Record("lua_counter", lua_isnumber(L, -1) ? lua_tonumber(L, -1) : -1);
    lua_pop(L, 1);
    lua_getglobal(L, "state");
    lua_getfield(L, -1, "energy");
    Record("lua_energy", lua_tonumber(L, -1));
    lua_getfield(L, -2, "missing");
    Record("lua_missing_is_nil", lua_isnil(L, -1));
    lua_pop(L, 3);
  }
  void PostStep() override {
    Record("post_step", GetSpace().GetSimulationClock());
    if (GetSpace().GetSimulationClock() != 2) return;
    CFootBotEntity* pcLate = new CFootBotEntity("fb_late", "student", CVector3(-1.5, 1.5, 0));
    AddEntity(*pcLate);  // after Init too: its init() runs now, its step() from the next tick
    Record("late_robot_ok", dynamic_cast<CLuaController&>(pcLate->GetControllableEntity().GetController()).IsOK());
    Record("foot_bots_after_late_add", GetSpace().GetEntitiesByType("foot-bot").size());
  }
  bool IsExperimentFinished() override { return GetSpace().GetSimulationClock() >= 3; }
  void PostExperiment() override { Record("post_experiment", GetSpace().GetSimulationClock()); }
  void Destroy() override {
    Record("destroy", 1);
    m_cOut.close();
  }

 private:
  template <typename T>
  void Record(const std::string& str_key, const T& t_value) {
    m_cOut << str_key << " " << t_value << std::endl;
  }

  void ReadConfiguration(TConfigurationNode& t_tree) {
    TConfigurationNode& tCensus = GetNode(t_tree, "census");
    std::string strOutput;
    GetNodeAttribute(tCensus, "output", strOutput);
    m_cOut.open(strOutput.c_str());
    CVector2 cPoint;
    CVector3 cCorner;
    bool bFlag = false;
    UInt32 unCount = 0;
    Real fDefaulted = 0;
    GetNodeAttribute(tCensus, "point", cPoint);
    GetNodeAttribute(tCensus, "corner", cCorner);
    GetNodeAttribute(tCensus, "flag", bFlag);
    GetNodeAttribute(tCensus, "count", unCount);
    GetNodeAttributeOrDefault(tCensus, "absent", fDefaulted, 2.5);
    Record("point", cPoint);
    Record("corner", cCorner);
    Record("flag", bFlag);
    Record("count", unCount);
    Record("defaulted", fDefaulted);
    Record("has_census", NodeExists(t_tree, "census"));
    std::string strChildren;
    TConfigurationNodeIterator itChild;
    for (itChild = itChild.begin(&t_tree); itChild != itChild.end(); ++itChild) strChildren += itChild->Value() + ";";
    Record("children", strChildren);
    try {
      GetNodeAttribute(tCensus, "nowhere", fDefaulted);
    } catch (CARGoSException& ex) {
      Record("missing_attribute_throws", 1);
    }
  }

  void ReadSpace() {
    Record("foot_bots", GetSpace().GetEntitiesByType("foot-bot").size());
    Record("boxes", GetSpace().GetEntitiesByType("box").size());
    Record("cylinders", GetSpace().GetEntitiesByType("cylinder").size());
    Record("lights", GetSpace().GetEntitiesByType("light").size());
    CFootBotEntity& cRobot = *any_cast<CFootBotEntity*>(GetSpace().GetEntitiesByType("foot-bot")["fb1"]);
    Record("fb1_x", cRobot.GetEmbodiedEntity().GetOriginAnchor().Position.GetX());
    Record("fb1_controller", dynamic_cast<CLuaController&>(cRobot.GetControllableEntity().GetController()).GetId());
    CBoxEntity& cCrate = *any_cast<CBoxEntity*>(GetSpace().GetEntitiesByType("box")["crate"]);
    CRadians cZ, cY, cX;
    cCrate.GetEmbodiedEntity().GetOriginAnchor().Orientation.ToEulerAngles(cZ, cY, cX);
    Record("crate_yaw_degrees", ToDegrees(cZ).GetValue());
    Record("crate_size_x", cCrate.GetSize().GetX());
    Record("crate_movable", cCrate.GetEmbodiedEntity().IsMovable());
    CLightEntity& cLamp = *any_cast<CLightEntity*>(GetSpace().GetEntitiesByType("light")["lamp"]);
    Record("lamp_intensity", cLamp.GetIntensity());
    Record("arena_x", GetSpace().GetArenaSize().GetX());
    try {
      GetSpace().GetEntitiesByType("nothing");
    } catch (CARGoSException& ex) {
      Record("unknown_type_throws", 1);
    }
  }

  void DrawNumbers() {
    CRandom::CRNG* pcRNG = CRandom::CreateRNG("argos");
    bool bInRange = true;
    for (int i = 0; i < 100; ++i) {
      Real fReal = pcRNG->Uniform(CRange<Real>(-1, 1));
      UInt32 unInt = pcRNG->Uniform(CRange<UInt32>(3, 7));
      CRadians cAngle = pcRNG->Uniform(CRadians::UNSIGNED_RANGE);
      bInRange = bInRange && fReal >= -1 && fReal <= 1 && unInt >= 3 && unInt < 7 &&
                 CRadians::UNSIGNED_RANGE.WithinMinBoundIncludedMaxBoundIncluded(cAngle);
      pcRNG->Gaussian(1.0);
      pcRNG->Bernoulli(0.3);
    }
    Record("rng_in_range", bInRange);
    Record("rng_first_of_second", CRandom::CreateRNG("argos")->Uniform(CRange<Real>(0, 1)));
  }

  void AddAndRemove() {
    CLEDMedium& cLEDs = CSimulator::GetInstance().GetMedium<CLEDMedium>("leds");
    CCylinderEntity* pcCylinder =
        new CCylinderEntity("added_cylinder", CVector3(-1, 1, 0), CQuaternion(), true, 0.05, 0.1, 0.2);
    pcCylinder->GetLEDEquippedEntity().AddLED(CVector3(0, 0, 0.1), CColor::GREEN);
    pcCylinder->GetLEDEquippedEntity().AddToMedium(cLEDs);
    AddEntity(*pcCylinder);
    CLightEntity* pcLight = new CLightEntity("added_light", CVector3(1, 1, 0.5), CColor::YELLOW, 1.5);
    pcLight->AddToMedium(cLEDs);
    AddEntity(*pcLight);
    CBoxEntity* pcBox = new CBoxEntity("added_box", CVector3(-1, -1, 0), CQuaternion(), false, CVector3(0.2, 0.2, 0.2));
    AddEntity(*pcBox);
    Record("cylinders_after_add", GetSpace().GetEntitiesByType("cylinder").size());
    Record("lights_after_add", GetSpace().GetEntitiesByType("light").size());
    Record("added_led_green", pcCylinder->GetLEDEquippedEntity().GetLED(0).GetColor() == CColor::GREEN);
    RemoveEntity(*pcBox);
    Record("boxes_after_remove", GetSpace().GetEntitiesByType("box").size());
    AddFootBots();
  }

  // ARGoS's custom-distribution example: a robot added at the origin (over fb0), then moved
  // somewhere free; its controller ran init() during AddEntity.
  void AddFootBots() {
    CFootBotEntity* pcRobot = new CFootBotEntity("fb9", "student");
    AddEntity(*pcRobot);
    Record("foot_bots_after_add", GetSpace().GetEntitiesByType("foot-bot").size());
    Record("added_robot_moved", MoveEntity(pcRobot->GetEmbodiedEntity(), CVector3(1.5, -1.5, 0), CQuaternion()));
    Record("added_robot_x", pcRobot->GetEmbodiedEntity().GetOriginAnchor().Position.GetX());
    Record("added_robot_leds", pcRobot->GetLEDEquippedEntity().GetLEDs().size());
    lua_State* L = dynamic_cast<CLuaController&>(pcRobot->GetControllableEntity().GetController()).GetLuaState();
    lua_getglobal(L, "counter");
    Record("added_robot_counter", lua_tonumber(L, -1));
    lua_pop(L, 1);
    Record("add_unknown_controller_throws", AddThrows(new CFootBotEntity("fb10", "nobody", CVector3(-1.5, -1.5, 0))));
    Record("add_duplicate_id_throws", AddThrows(new CFootBotEntity("fb0", "student", CVector3(-1.5, -1.5, 0))));
    Record("add_outside_throws", AddThrows(new CFootBotEntity("fb11", "student", CVector3(9, 0, 0))));
    Record("add_bad_rab_range_throws",
           AddThrows(new CFootBotEntity("fb12", "student", CVector3(-1.5, -1.5, 0), CQuaternion(), -1)));
  }

  /// Whether AddEntity refuses `pc_robot` (then still the caller's, deleted here).
  bool AddThrows(CFootBotEntity* pc_robot) {
    try {
      AddEntity(*pc_robot);
      return false;
    } catch (CARGoSException& ex) {
      delete pc_robot;
      return true;
    }
  }

  void MoveAndColour() {
    CBoxEntity& cCrate = *any_cast<CBoxEntity*>(GetSpace().GetEntitiesByType("box")["crate"]);
    CEmbodiedEntity& cBody = cCrate.GetEmbodiedEntity();
    const CQuaternion cOrientation = cBody.GetOriginAnchor().Orientation;
    Record("move_onto_robot", MoveEntity(cBody, CVector3(1, 0, 0), cOrientation));
    Record("move_check_only", MoveEntity(cBody, CVector3(0, 1.5, 0), cOrientation, true));
    Record("crate_x_after_check", cBody.GetOriginAnchor().Position.GetX());
    Record("move_free", MoveEntity(cBody, CVector3(0, 1.5, 0), cOrientation));
    Record("crate_y_after_move", cBody.GetOriginAnchor().Position.GetY());
    cCrate.GetLEDEquippedEntity().SetAllLEDsColors(CColor::BLUE);
    Record("crate_led_blue", cCrate.GetLEDEquippedEntity().GetLED(0).GetColor() == CColor::BLUE);
    CLightEntity& cLamp = *any_cast<CLightEntity*>(GetSpace().GetEntitiesByType("light")["lamp"]);
    cLamp.SetIntensity(2.5);
    Record("lamp_intensity_set", cLamp.GetIntensity());
  }

  std::ofstream m_cOut;
};

REGISTER_LOOP_FUNCTIONS(CCensusLoopFunctions, "census_loop_functions")
