// ARGoS's CSimulator (argos3/core/simulator/simulator.h): the running experiment, reached
// through CSimulator::GetInstance() while one of the loop functions' hooks or a robot's C++
// controller runs.
#pragma once
#include <argos3/core/simulator/medium/medium.h>
#include <argos3/core/simulator/physics_engine/physics_engine.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/utility/configuration/argos_exception.h>
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/math/rng.h>

#include <string>

namespace argos {

class CLoopFunctions;

class CSimulator {
 public:
  /// The experiment whose loop functions are running; throws outside their hooks.
  static CSimulator& GetInstance();
  CSpace& GetSpace();
  CLoopFunctions& GetLoopFunctions();
  /// The <media> member with id `str_id`, as a T (CLEDMedium); throws when there is none.
  template <typename T>
  T& GetMedium(const std::string& str_id) {
    T* medium = dynamic_cast<T*>(&GetMediumById(str_id));
    if (!medium) THROW_ARGOSEXCEPTION("medium \"" << str_id << "\" is not of the type asked for");
    return *medium;
  }
  CMedium& GetMediumById(const std::string& str_id);
  /// The physics engine: one object for any id (ARGoS's Release build checks none).
  CPhysicsEngine& GetPhysicsEngine(const std::string& str_id) const;
  CPhysicsEngine::TVector& GetPhysicsEngines();
  UInt32 GetRandomSeed() const;
  /// The experiment's length in ticks (0: unlimited).
  UInt32 GetMaxSimulationClock() const;
  bool IsRealTimeClock() const { return false; }

 private:
  friend struct SSessionAccess;
  CSimulator() = default;
};

}  // namespace argos
