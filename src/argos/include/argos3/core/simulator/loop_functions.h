// ARGoS's CLoopFunctions (argos3/core/simulator/loop_functions.h): experiment logic in C++,
// built against essaim's ARGoS API and loaded with
// <loop_functions library="build/libNAME" label="NAME"> (docs/loop-functions.md). Hooks run
// at the points of the tick where Lua loop functions' do.
#pragma once
#include <argos3/core/control_interface/ci_controller.h>  // ARGoS: through space.h; the API version
#include <argos3/core/simulator/entity/embodied_entity.h>
#include <argos3/core/simulator/entity/positional_entity.h>
#include <argos3/core/simulator/simulator.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/utility/datatypes/color.h>
#include <argos3/core/utility/logging/argos_log.h>
#include <argos3/core/utility/math/quaternion.h>
#include <argos3/core/utility/math/vector2.h>
#include <argos3/core/utility/math/vector3.h>

#include <functional>

namespace argos {

class CLoopFunctions {
 public:
  /// Made while the experiment is current (essaim makes it before Init), as ARGoS's.
  CLoopFunctions();
  virtual ~CLoopFunctions() = default;
  virtual void Init(TConfigurationNode& t_tree) { (void)t_tree; }
  virtual void Reset() {}
  virtual void Destroy() {}
  virtual void PreStep() {}
  virtual void PostStep() {}
  virtual bool IsExperimentFinished() { return false; }
  virtual void PostExperiment() {}
  /// The floor's colour at a point, when the floor is <floor source="loop_functions">.
  virtual CColor GetFloorColor(const CVector2& c_position_on_plane) {
    (void)c_position_on_plane;
    return CColor::WHITE;  // ARGoS's since 3.0.0-beta29 (black before)
  }
  CSimulator& GetSimulator() { return m_cSimulator; }
  CSpace& GetSpace() { return m_cSpace; }
  /// Puts a box, cylinder or light made with `new` into the space, which owns it from then on.
  void AddEntity(CEntity& c_entity);
  /// Removes a box, cylinder or light (the space deletes it).
  void RemoveEntity(CEntity& c_entity);
  void RemoveEntity(const std::string& str_entity_id);
  /// Teleports a body unless it would overlap another; whether it fits.
  bool MoveEntity(CEmbodiedEntity& c_entity, const CVector3& c_position, const CQuaternion& c_orientation,
                  bool b_check_only = false, bool b_ignore_collisions = false) {
    return c_entity.MoveTo(c_position, c_orientation, b_check_only, b_ignore_collisions);
  }
  /// ARGoS's for any positional entity: a body moves as above, a light always. Until ARGoS
  /// 3.0.0-beta30 the only MoveEntity, taking `b_check_only` and saying whether it fit.
  bool MoveEntity(CPositionalEntity& c_entity, const CVector3& c_position, const CQuaternion& c_orientation,
                  bool b_check_only = false);

 protected:
  /// ARGoS's until 3.0.0-beta18, when GetSimulator() and GetSpace() took their place; kept
  /// for the loop functions of that time, which use them directly.
  CSimulator& m_cSimulator;
  CSpace& m_cSpace;
};

typedef CLoopFunctions* (*TLoopFunctionsCreator)();
/// Called by REGISTER_LOOP_FUNCTIONS when the library is loaded.
bool RegisterLoopFunctions(const char* str_label, TLoopFunctionsCreator pf_creator, int n_api_version);

}  // namespace argos

/// Makes class CLASSNAME the loop functions named LABEL in <loop_functions label="LABEL">.
#define REGISTER_LOOP_FUNCTIONS(CLASSNAME, LABEL)                                                            \
  namespace {                                                                                                \
  const bool ARGOS_ESSAIM_CONCAT(argos_loop_functions_registered_, __LINE__) = argos::RegisterLoopFunctions( \
      LABEL, []() -> argos::CLoopFunctions* { return new CLASSNAME; }, ARGOS_ESSAIM_API_VERSION);            \
  }
