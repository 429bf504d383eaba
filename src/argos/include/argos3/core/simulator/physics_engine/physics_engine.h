// ARGoS's CPhysicsEngine (argos3/core/simulator/physics_engine/physics_engine.h), as far as
// loop functions and controllers reach it: the simulation clock's tick, a static as in ARGoS.
// essaim steps its own physics; CSimulator::GetPhysicsEngine(id) answers one object for any id
// (a Release ARGoS does not check the id either).
#pragma once
#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/logging/argos_log.h>
#include <argos3/core/utility/math/vector2.h>  // ARGoS: through ray2.h

#include <map>
#include <string>
#include <vector>

namespace argos {

class CPhysicsEngine {
 public:
  typedef std::vector<CPhysicsEngine*> TVector;
  typedef std::map<std::string, CPhysicsEngine*, std::less<std::string>> TMap;

  explicit CPhysicsEngine(const std::string& str_id) : m_strId(str_id) {}
  virtual ~CPhysicsEngine() {}
  /// Seconds per tick (1 / ticks_per_second), and its inverse.
  static Real GetSimulationClockTick();
  static Real GetInverseSimulationClockTick();
  static void SetSimulationClockTick(Real f_simulation_clock_tick);
  const std::string& GetId() const { return m_strId; }

 private:
  std::string m_strId;
};

}  // namespace argos
