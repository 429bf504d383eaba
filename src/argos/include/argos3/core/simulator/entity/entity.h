// ARGoS's CEntity (argos3/core/simulator/entity/entity.h): what every entity has, an id and
// a type. An entity from the .argos file, or one that AddEntity put in the space, stands
// for an entity of essaim's world (devices/entity_store.h): reading it reads the world.
#pragma once
#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/logging/argos_log.h>  // ARGoS: through its plugin factory

#include <string>

namespace argos {

class CEntity {
 public:
  explicit CEntity(const std::string& str_id) : m_strId(str_id) {}
  virtual ~CEntity() = default;
  CEntity(const CEntity&) = delete;
  CEntity& operator=(const CEntity&) = delete;
  const std::string& GetId() const { return m_strId; }
  virtual std::string GetTypeDescription() const { return "entity"; }
  bool HasParent() const { return m_pcParent != nullptr; }
  /// The entity this one is a component of; throws for a root entity.
  CEntity& GetParent();
  /// The entity at the root of the component tree.
  CEntity& GetRootEntity();
  const CEntity& GetRootEntity() const;
  /// Whether this entity's root is in the space now (added and not removed).
  bool IsInSpace() const;

 protected:
  CEntity(CEntity* pc_parent, const std::string& str_id) : m_strId(str_id), m_pcParent(pc_parent) {}

 private:
  friend struct SEntityBinding;  // essaim's: binds a root entity to the world's entity
  std::string m_strId;
  CEntity* m_pcParent = nullptr;
  SInt32 m_nWorldKind = -1;  // essaim's entity kind (foot-bot 0, box 1, cylinder 2, light 3); -1: not in space
  UInt32 m_unWorldSerial = 0;
};

}  // namespace argos
