// The C++ sources of `essaim new NAME --template cpp`: a controller and loop functions written
// against ARGoS's API as argos3-examples' are (CCI_Controller, GetSensor/GetActuator,
// GetNodeAttributeOrDefault, CRandom, LOG). @CLASS@ is the name in CamelCase, @GUARD@ in capitals;
// project_cpp_files.cpp fills them in.
#include "app/project_templates.h"

namespace essaim {

const char* const kCppControllerHeader =
    R"(/* @NAME@: aggregation (essaim new @NAME@ --template cpp). Each robot tells the others it is
 * there (range-and-bearing), steers towards the mean bearing of the robots it hears, wanders
 * when it hears none, and turns away from what is close in front (proximity). LEDs: green while
 * it hears others, yellow while alone, red when it has arrived. */
#ifndef @GUARD@_H
#define @GUARD@_H

#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_leds_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_sensor.h>

using namespace argos;

class C@CLASS@ : public CCI_Controller {
 public:
  C@CLASS@();
  virtual ~C@CLASS@() {}
  /* Once, with the <params> element of the .argos file's controller entry. */
  virtual void Init(TConfigurationNode& t_node);
  /* Every tick: read the sensors, set the actuators. */
  virtual void ControlStep();
  virtual void Reset();
  virtual void Destroy() {}

 private:
  /* The largest proximity reading within 60 degrees of the front, and its angle. */
  Real Obstacle(CRadians& c_angle) const;
  /* Turns towards c_angle (robot's frame) at m_fSpeed. */
  void Steer(const CRadians& c_angle);

  CCI_DifferentialSteeringActuator* m_pcWheels;
  CCI_LEDsActuator* m_pcLEDs;
  CCI_RangeAndBearingActuator* m_pcRABA;
  CCI_RangeAndBearingSensor* m_pcRABS;
  CCI_FootBotProximitySensor* m_pcProximity;
  CRandom::CRNG* m_pcRNG;
  Real m_fSpeed;    /* cm/s, <params speed="..."> */
  Real m_fArrived;  /* proximity reading at which the robot stops, <params arrived="..."> */
};

#endif
)";

const char* const kCppController = R"(#include "@NAME@.h"

#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/utility/math/vector2.h>

C@CLASS@::C@CLASS@()
    : m_pcWheels(NULL),
      m_pcLEDs(NULL),
      m_pcRABA(NULL),
      m_pcRABS(NULL),
      m_pcProximity(NULL),
      m_pcRNG(NULL),
      m_fSpeed(10.0),
      m_fArrived(0.5) {}

void C@CLASS@::Init(TConfigurationNode& t_node) {
  /* The names are the .argos file's <actuators> and <sensors> elements. */
  m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
  m_pcLEDs = GetActuator<CCI_LEDsActuator>("leds");
  m_pcRABA = GetActuator<CCI_RangeAndBearingActuator>("range_and_bearing");
  m_pcRABS = GetSensor<CCI_RangeAndBearingSensor>("range_and_bearing");
  m_pcProximity = GetSensor<CCI_FootBotProximitySensor>("footbot_proximity");
  GetNodeAttributeOrDefault(t_node, "speed", m_fSpeed, m_fSpeed);
  GetNodeAttributeOrDefault(t_node, "arrived", m_fArrived, m_fArrived);
  /* Seeded from the experiment's random_seed: the same run at any thread count. */
  m_pcRNG = CRandom::CreateRNG("argos");
  Reset();
}

void C@CLASS@::Reset() {
  m_pcRABA->SetData(0, 1);
  m_pcLEDs->SetAllColors(CColor::GREEN);
}

Real C@CLASS@::Obstacle(CRadians& c_angle) const {
  const CCI_FootBotProximitySensor::TReadings& tProx = m_pcProximity->GetReadings();
  Real fValue = 0.0;
  c_angle = CRadians::ZERO;
  for (size_t i = 0; i < tProx.size(); ++i) {
    if (Abs(tProx[i].Angle) < CRadians::PI_OVER_THREE && tProx[i].Value > fValue) {
      fValue = tProx[i].Value;
      c_angle = tProx[i].Angle;
    }
  }
  return fValue;
}

void C@CLASS@::Steer(const CRadians& c_angle) {
  Real fTurn = c_angle.GetValue() / CRadians::PI_OVER_TWO.GetValue();
  if (fTurn > 1.0) fTurn = 1.0;
  if (fTurn < -1.0) fTurn = -1.0;
  m_pcWheels->SetLinearVelocity(m_fSpeed * (1.0 - fTurn), m_fSpeed * (1.0 + fTurn));
}

void C@CLASS@::ControlStep() {
  CRadians cSide;
  const Real fClose = Obstacle(cSide);
  /* The mean bearing of the robots heard: a sum of unit vectors. */
  const CCI_RangeAndBearingSensor::TReadings& tHeard = m_pcRABS->GetReadings();
  CVector2 cSum;
  for (size_t i = 0; i < tHeard.size(); ++i) cSum += CVector2(1.0, tHeard[i].HorizontalBearing);
  if (fClose > m_fArrived) {
    m_pcWheels->SetLinearVelocity(0.0, 0.0); /* another robot (or a wall) right in front */
    m_pcLEDs->SetAllColors(CColor::RED);
  } else if (fClose > 0.1) {
    Steer(cSide.GetValue() > 0.0 ? -CRadians::PI_OVER_TWO : CRadians::PI_OVER_TWO);
  } else if (!tHeard.empty()) {
    Steer(cSum.Angle());
    m_pcLEDs->SetAllColors(CColor::GREEN);
  } else {
    Steer(m_pcRNG->Uniform(CRange<CRadians>(-CRadians::PI_OVER_TWO, CRadians::PI_OVER_TWO)));
    m_pcLEDs->SetAllColors(CColor::YELLOW);
  }
}

/* The label is the tag of the .argos file's controller entry. */
REGISTER_CONTROLLER(C@CLASS@, "@NAME@_controller")
)";

const char* const kCppLoopHeader =
    R"(/* @NAME@'s loop functions (essaim new @NAME@ --template cpp): how much the swarm gathered.
 * Every <params every="..."/> ticks, a row of <params output="..."/> (spread.csv): the tick,
 * the spread (the robots' mean distance to their centre, m) and the shrink (the spread over
 * the spread at start: below 1, the swarm gathered). essaim runs in the run's files/ folder,
 * so the file lands in runs/@NAME@-SEED/files/ and essaim test reads its columns. */
#ifndef @GUARD@_LOOP_FUNCTIONS_H
#define @GUARD@_LOOP_FUNCTIONS_H

#include <argos3/core/simulator/loop_functions.h>

#include <cstdio>
#include <string>

using namespace argos;

class C@CLASS@LoopFunctions : public CLoopFunctions {
 public:
  C@CLASS@LoopFunctions() : m_pFile(NULL), m_unEvery(50), m_fSpreadStart(0.0), m_unLastRow(0) {}
  virtual void Init(TConfigurationNode& t_tree);
  virtual void PostStep();
  virtual void PostExperiment();
  virtual void Destroy();

 private:
  Real Spread();
  void WriteRow();

  std::FILE* m_pFile;
  UInt32 m_unEvery;
  Real m_fSpreadStart;
  UInt32 m_unLastRow;
};

#endif
)";

const char* const kCppLoop = R"(#include "@NAME@_loop_functions.h"

#include <argos3/core/utility/logging/argos_log.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>

void C@CLASS@LoopFunctions::Init(TConfigurationNode& t_tree) {
  std::string strOutput = "spread.csv";
  TConfigurationNode& tParams = GetNode(t_tree, "params");
  GetNodeAttributeOrDefault(tParams, "output", strOutput, strOutput);
  GetNodeAttributeOrDefault(tParams, "every", m_unEvery, m_unEvery);
  m_pFile = std::fopen(strOutput.c_str(), "w");
  if (m_pFile == NULL) THROW_ARGOSEXCEPTION("cannot write " << strOutput);
  std::fprintf(m_pFile, "tick,spread,shrink\n");
  m_fSpreadStart = Spread();
  WriteRow();
}

Real C@CLASS@LoopFunctions::Spread() {
  CSpace::TMapPerType& tRobots = GetSpace().GetEntitiesByType("foot-bot");
  CVector3 cCentre;
  for (CSpace::TMapPerType::iterator it = tRobots.begin(); it != tRobots.end(); ++it)
    cCentre += any_cast<CFootBotEntity*>(it->second)->GetEmbodiedEntity().GetOriginAnchor().Position;
  cCentre /= tRobots.size();
  Real fSum = 0.0;
  for (CSpace::TMapPerType::iterator it = tRobots.begin(); it != tRobots.end(); ++it)
    fSum += (any_cast<CFootBotEntity*>(it->second)->GetEmbodiedEntity().GetOriginAnchor().Position - cCentre).Length();
  return fSum / tRobots.size();
}

void C@CLASS@LoopFunctions::WriteRow() {
  const Real fSpread = Spread();
  m_unLastRow = GetSpace().GetSimulationClock();
  std::fprintf(m_pFile, "%u,%.6f,%.6f\n", m_unLastRow, fSpread, fSpread / m_fSpreadStart);
}

void C@CLASS@LoopFunctions::PostStep() {
  if (GetSpace().GetSimulationClock() % m_unEvery == 0) WriteRow();
}

void C@CLASS@LoopFunctions::PostExperiment() {
  if (GetSpace().GetSimulationClock() != m_unLastRow) WriteRow();
  LOG << "spread: " << m_fSpreadStart << " m at start, " << Spread() << " m at the end" << std::endl;
}

void C@CLASS@LoopFunctions::Destroy() {
  if (m_pFile != NULL) std::fclose(m_pFile);
  m_pFile = NULL;
}

/* The label is the .argos file's <loop_functions label="...">. */
REGISTER_LOOP_FUNCTIONS(C@CLASS@LoopFunctions, "@NAME@_loop_functions")
)";

}  // namespace essaim
