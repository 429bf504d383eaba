// Inside the ARGoS API library: which world entity an ARGoS entity stands for, and the
// space's wrappers of the world's entities (made at first sight, kept while they live).
#pragma once
#include <argos3/core/simulator/space/space.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

#include "argos/argos_world.h"

namespace argos {

class CFootBotEntity;

struct CSpace::SWorldEntities {
  /// Wrappers by (kind, serial): the world's own entities, and those AddEntity adopted.
  std::map<std::pair<int, UInt32>, std::unique_ptr<CEntity>> wrappers;
  bool kind_seen[4] = {false, false, false, false};
  /// GetEntitiesByType's maps, kept until an entity is added or removed (LayoutVersion).
  CSpace::TMapPerType by_type[4];
  uint64_t by_type_version[4] = {~0ull, ~0ull, ~0ull, ~0ull};
  /// GetEntity's index: each id's first entity in creation order, kept as by_type is.
  std::unordered_map<std::string, essaim::ArgosRef> by_id;
  uint64_t by_id_version = ~0ull;
  /// Held by the space's lookups made from a robot's ControlStep, which runs beside other
  /// robots': the wrappers and maps are made once, then only read until the next stage.
  std::mutex step_lock;
};

struct SEntityBinding {
  static void Bind(CEntity& c_entity, const essaim::ArgosRef& ref) {
    c_entity.m_nWorldKind = ref.kind;
    c_entity.m_unWorldSerial = ref.serial;
  }
  static void Unbind(CEntity& c_entity) { c_entity.m_nWorldKind = -1; }
  /// The world entity `c_entity`'s root stands for; false when it is not in the space.
  static bool Find(const CEntity& c_entity, essaim::ArgosRef* ref) {
    const CEntity& root = c_entity.GetRootEntity();
    if (root.m_nWorldKind < 0) return false;
    ref->kind = root.m_nWorldKind;
    ref->serial = root.m_unWorldSerial;
    return true;
  }
  /// As Find, and the entity must still be live; throws naming `what` otherwise.
  static essaim::ArgosRef Require(const CEntity& c_entity, const char* what);
  static CSpace::SWorldEntities& Entities(CSpace& c_space) { return *c_space.m_psEntities; }
  /// What AddEntity asks the world for, from a CFootBotEntity's constructor arguments.
  static essaim::ArgosRobot RobotSpec(const CFootBotEntity& c_robot);
  /// The wrapper of world entity `ref`, made at its first use.
  static CEntity& Wrapper(CSpace& c_space, const essaim::ArgosRef& ref);
};

}  // namespace argos
