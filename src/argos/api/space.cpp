// CSpace and CSimulator over the current session's world, and the loop functions' entity
// operations (AddEntity, RemoveEntity).
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <argos3/plugins/simulator/entities/box_entity.h>
#include <argos3/plugins/simulator/entities/cylinder_entity.h>
#include <argos3/plugins/simulator/entities/light_entity.h>

#include "argos/api/entity_binding.h"
#include "argos/api/entity_specs.h"
#include "argos/api/session_state.h"

namespace argos {

namespace {
const char* const kTypeNames[] = {"foot-bot", "box", "cylinder", "light"};

CAny Typed(CEntity& c_entity, int kind) {
  switch (kind) {
    case essaim::kArgosFootBot:
      return CAny(static_cast<CFootBotEntity*>(&c_entity));
    case essaim::kArgosBox:
      return CAny(static_cast<CBoxEntity*>(&c_entity));
    case essaim::kArgosCylinder:
      return CAny(static_cast<CCylinderEntity*>(&c_entity));
    default:
      return CAny(static_cast<CLightEntity*>(&c_entity));
  }
}
}  // namespace

CSpace::CSpace() : m_psEntities(new SWorldEntities) {}
CSpace::~CSpace() = default;

namespace {
// The space's lock, taken only inside a robot's ControlStep (robots step on several threads).
std::unique_lock<std::mutex> StepLock(std::mutex& lock) {
  const essaim::ArgosControllerCall* call = essaim::CurrentControllerCall();
  return call && call->parallel ? std::unique_lock<std::mutex>(lock) : std::unique_lock<std::mutex>();
}
}  // namespace

CSpace::TMapPerType& CSpace::GetEntitiesByType(const std::string& str_type) {
  essaim::ArgosWorld& world = *essaim::RequireSession("GetEntitiesByType").world;
  const std::unique_lock<std::mutex> hold = StepLock(m_psEntities->step_lock);
  int kind = 0;
  while (kind < 4 && str_type != kTypeNames[kind]) ++kind;
  if (kind == 4) THROW_ARGOSEXCEPTION("Entity map for type \"" << str_type << "\" not found.");
  TMapPerType& cached = m_psEntities->by_type[kind];
  const uint64_t version = world.LayoutVersion();
  if (m_psEntities->by_type_version[kind] != version) {  // made again only after an addition or removal
    cached.clear();
    for (const essaim::ArgosRef& ref : world.Entities(kind)) {
      CEntity& wrapper = SEntityBinding::Wrapper(*this, ref);
      cached.emplace(wrapper.GetId(), Typed(wrapper, kind));
    }
    m_psEntities->by_type_version[kind] = version;
    if (!cached.empty()) m_psEntities->kind_seen[kind] = true;
  }
  // ARGoS keeps one map per type that ever had an entity, and throws for any other type.
  if (!m_psEntities->kind_seen[kind]) THROW_ARGOSEXCEPTION("Entity map for type \"" << str_type << "\" not found.");
  return cached;
}

CEntity& CSpace::GetEntity(const std::string& str_id) {
  essaim::ArgosWorld& world = *essaim::RequireSession("GetEntity").world;
  const std::unique_lock<std::mutex> hold = StepLock(m_psEntities->step_lock);
  auto& by_id = m_psEntities->by_id;
  const uint64_t version = world.LayoutVersion();
  if (m_psEntities->by_id_version != version) {  // a lookup, not a scan; made again after an addition or removal
    by_id.clear();
    for (const essaim::ArgosRef& ref : world.Entities(-1)) by_id.emplace(world.Id(ref), ref);
    m_psEntities->by_id_version = version;
  }
  const auto found = by_id.find(str_id);
  if (found != by_id.end()) return SEntityBinding::Wrapper(*this, found->second);
  THROW_ARGOSEXCEPTION("No entity with id \"" << str_id << "\" in the space");
}

UInt32 CSpace::GetSimulationClock() const {
  return static_cast<UInt32>(essaim::RequireSession("GetSimulationClock").world->Tick());
}

const CVector3& CSpace::GetArenaSize() const {
  static thread_local CVector3 size;
  double s[3], c[3];
  essaim::RequireSession("GetArenaSize").world->Arena(s, c);
  size.Set(s[0], s[1], s[2]);
  return size;
}

const CVector3& CSpace::GetArenaCenter() const {
  static thread_local CVector3 center;
  double s[3], c[3];
  essaim::RequireSession("GetArenaCenter").world->Arena(s, c);
  center.Set(c[0], c[1], c[2]);
  return center;
}

CSimulator& CSimulator::GetInstance() { return essaim::RequireSession("CSimulator::GetInstance").simulator; }
CSpace& CSimulator::GetSpace() { return essaim::RequireSession("GetSpace").space; }

CLoopFunctions& CSimulator::GetLoopFunctions() {
  essaim::ArgosSession::State& session = essaim::RequireSession("GetLoopFunctions");
  if (!session.loop_functions)
    THROW_ARGOSEXCEPTION("GetLoopFunctions: the experiment has no C++ loop functions"
                         << " (none declared, or they are being made)");
  return *session.loop_functions;
}

CMedium& CSimulator::GetMediumById(const std::string& str_id) {
  essaim::ArgosSession::State& session = essaim::RequireSession("GetMedium");
  auto found = session.media.find(str_id);
  if (found == session.media.end()) THROW_ARGOSEXCEPTION("Medium \"" << str_id << "\" not found (only <led> media)");
  return *found->second;
}

CPhysicsEngine& CSimulator::GetPhysicsEngine(const std::string&) const {
  return essaim::RequireSession("GetPhysicsEngine").physics;
}
CPhysicsEngine::TVector& CSimulator::GetPhysicsEngines() {
  return essaim::RequireSession("GetPhysicsEngines").physics_engines;
}

namespace {
Real simulation_clock_tick = 0.1;  // ARGoS's is a static too; each session sets it
}  // namespace
Real CPhysicsEngine::GetSimulationClockTick() { return simulation_clock_tick; }
Real CPhysicsEngine::GetInverseSimulationClockTick() { return 1 / simulation_clock_tick; }
void CPhysicsEngine::SetSimulationClockTick(Real f_simulation_clock_tick) {
  simulation_clock_tick = f_simulation_clock_tick;
}

UInt32 CSimulator::GetRandomSeed() const {
  return static_cast<UInt32>(essaim::RequireSession("GetRandomSeed").world->Seed());
}

UInt32 CSimulator::GetMaxSimulationClock() const {
  return static_cast<UInt32>(essaim::RequireSession("GetMaxSimulationClock").world->LengthTicks());
}

// The space's wrappers of the world's entities are made now, while every entity of the .argos
// file stands where it started: GetInitPosition() reports that place.
CLoopFunctions::CLoopFunctions() : m_cSimulator(CSimulator::GetInstance()), m_cSpace(m_cSimulator.GetSpace()) {
  for (const essaim::ArgosRef& ref : essaim::RequireSession("CLoopFunctions").world->Entities(-1))
    SEntityBinding::Wrapper(m_cSpace, ref);
}

bool CLoopFunctions::MoveEntity(CPositionalEntity& c_entity, const CVector3& c_position,
                                const CQuaternion& c_orientation, bool b_check_only) {
  if (auto* body = dynamic_cast<CEmbodiedEntity*>(&c_entity))
    return body->MoveTo(c_position, c_orientation, b_check_only);
  if (!b_check_only) c_entity.SetPosition(c_position), c_entity.SetOrientation(c_orientation);
  return true;
}

void CLoopFunctions::AddEntity(CEntity& c_entity) {
  essaim::ArgosSession::State& session = essaim::RequireSession("AddEntity");
  if (c_entity.HasParent()) THROW_ARGOSEXCEPTION("AddEntity: \"" << c_entity.GetId() << "\" is a component");
  essaim::ArgosRef ref;
  if (SEntityBinding::Find(c_entity, &ref))
    THROW_ARGOSEXCEPTION("AddEntity: \"" << c_entity.GetId() << "\" is in the space already");
  std::string error;
  if (!AddToWorld(*session.world, c_entity, &ref, &error))
    THROW_ARGOSEXCEPTION("AddEntity(\"" << c_entity.GetId() << "\"): " << error);
  SEntityBinding::Bind(c_entity, ref);
  auto& entities = SEntityBinding::Entities(session.space);
  entities.wrappers[{ref.kind, ref.serial}].reset(&c_entity);  // the space owns it now
  entities.kind_seen[ref.kind] = true;
}

void CLoopFunctions::RemoveEntity(CEntity& c_entity) {
  essaim::ArgosSession::State& session = essaim::RequireSession("RemoveEntity");
  const essaim::ArgosRef ref = SEntityBinding::Require(c_entity, "RemoveEntity");
  if (ref.kind == essaim::kArgosFootBot)
    THROW_ARGOSEXCEPTION("RemoveEntity(\"" << c_entity.GetId() << "\"): essaim cannot remove foot-bots");
  session.world->Remove(ref);
  SEntityBinding::Entities(session.space).wrappers.erase({ref.kind, ref.serial});  // deletes it, as ARGoS
}

void CLoopFunctions::RemoveEntity(const std::string& str_entity_id) {
  RemoveEntity(GetSpace().GetEntity(str_entity_id));
}

}  // namespace argos
