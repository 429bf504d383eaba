// ARGoS's CSpace (argos3/core/simulator/space/space.h): the entities of the experiment.
// GetEntitiesByType("foot-bot" / "box" / "cylinder" / "light") maps each id to a CAny holding
// the entity's pointer (CFootBotEntity*, ...), ordered by id as ARGoS's std::map is.
#pragma once
#include <argos3/core/simulator/entity/controllable_entity.h>
#include <argos3/core/simulator/entity/embodied_entity.h>
#include <argos3/core/simulator/entity/floor_entity.h>
#include <argos3/core/simulator/medium/medium.h>
#include <argos3/core/utility/datatypes/any.h>
#include <argos3/core/utility/math/vector3.h>

#include <map>
#include <memory>
#include <string>

namespace argos {

class CSpace {
 public:
  typedef std::map<std::string, CAny, std::less<std::string>> TMapPerType;
  CSpace();
  ~CSpace();
  CSpace(const CSpace&) = delete;
  CSpace& operator=(const CSpace&) = delete;
  /// Every entity of `str_type` in the space; throws for a type no entity ever had (ARGoS).
  TMapPerType& GetEntitiesByType(const std::string& str_type);
  /// The entity with id `str_id`; throws when there is none.
  CEntity& GetEntity(const std::string& str_id);
  /// The current tick (0 in Init).
  UInt32 GetSimulationClock() const;
  CFloorEntity& GetFloorEntity() { return m_cFloor; }
  const CVector3& GetArenaSize() const;
  const CVector3& GetArenaCenter() const;

 private:
  friend struct SEntityBinding;
  struct SWorldEntities;
  std::unique_ptr<SWorldEntities> m_psEntities;
  CFloorEntity m_cFloor;
};

}  // namespace argos
