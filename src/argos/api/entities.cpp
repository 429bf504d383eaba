// The entity classes' members that read or change the world: through the current session,
// once the entity is in the space; before that, on the values it was made with.
#include <argos3/core/simulator/entity/controllable_entity.h>
#include <argos3/core/simulator/entity/embodied_entity.h>
#include <argos3/core/simulator/entity/floor_entity.h>
#include <argos3/core/simulator/entity/positional_entity.h>
#include <argos3/core/wrappers/lua/lua_controller.h>
#include <argos3/plugins/simulator/entities/led_equipped_entity.h>
#include <argos3/plugins/simulator/entities/light_entity.h>

#include "argos/api/entity_binding.h"
#include "argos/api/entity_specs.h"
#include "argos/api/session_state.h"

namespace argos {

namespace {
essaim::ArgosWorld& World(const char* what) { return *essaim::RequireSession(what).world; }
essaim::ArgosRgb Rgb(const CColor& c) { return {c.GetRed(), c.GetGreen(), c.GetBlue()}; }
}  // namespace

essaim::ArgosRef SEntityBinding::Require(const CEntity& c_entity, const char* what) {
  essaim::ArgosRef ref;
  if (!Find(c_entity, &ref) || !World(what).Live(ref))
    THROW_ARGOSEXCEPTION(what << ": \"" << c_entity.GetRootEntity().GetId() << "\" is not in the space");
  return ref;
}

CEntity& CEntity::GetParent() {
  if (!m_pcParent) THROW_ARGOSEXCEPTION("Entity \"" << m_strId << "\" has no parent");
  return *m_pcParent;
}

CEntity& CEntity::GetRootEntity() { return m_pcParent ? m_pcParent->GetRootEntity() : *this; }
const CEntity& CEntity::GetRootEntity() const { return m_pcParent ? m_pcParent->GetRootEntity() : *this; }

bool CEntity::IsInSpace() const {
  essaim::ArgosRef ref;
  return SEntityBinding::Find(*this, &ref) && World("IsInSpace").Live(ref);
}

namespace {
// Whether a pose set at `set_at` still hides the world's: until the physics updates the body
// (the next tick), never for a static body, which the physics does not update.
bool SetPoseShows(SInt64 set_at, const essaim::ArgosWorld& world, const essaim::ArgosRef& ref) {
  if (set_at < 0) return false;
  return static_cast<UInt64>(set_at) == world.Tick() || !world.Movable(ref);
}

// The world's pose of the entity `c_entity` stands for; false when it is not in the space.
bool WorldPose(const CEntity& c_entity, const char* what, essaim::ArgosRef* ref, essaim::ArgosPose* pose) {
  if (!SEntityBinding::Find(c_entity, ref)) return false;
  if (!World(what).Pose(*ref, pose))
    THROW_ARGOSEXCEPTION(what << ": \"" << c_entity.GetRootEntity().GetId() << "\" is not in the space");
  return true;
}
}  // namespace

const CVector3& CPositionalEntity::GetPosition() const {
  essaim::ArgosRef ref;
  essaim::ArgosPose pose;
  if (WorldPose(*this, "GetPosition", &ref, &pose) && !SetPoseShows(m_nPositionSetAt, World("GetPosition"), ref))
    m_cPosition.Set(pose.x, pose.y, pose.z);
  return m_cPosition;
}

const CQuaternion& CPositionalEntity::GetOrientation() const {
  essaim::ArgosRef ref;
  essaim::ArgosPose pose;
  if (WorldPose(*this, "GetOrientation", &ref, &pose) && ref.kind != essaim::kArgosLight &&
      !SetPoseShows(m_nOrientationSetAt, World("GetOrientation"), ref))
    m_cOrientation = FromYaw(pose.yaw);
  return m_cOrientation;
}

void CPositionalEntity::SetPosition(const CVector3& c_position) {
  m_cPosition = c_position;
  essaim::ArgosRef ref;
  if (!SEntityBinding::Find(*this, &ref)) return;
  ref = SEntityBinding::Require(*this, "SetPosition");
  if (ref.kind != essaim::kArgosLight) {  // a body: reported, not moved
    m_nPositionSetAt = static_cast<SInt64>(World("SetPosition").Tick());
    return;
  }
  essaim::ArgosLight light = World("SetPosition").Light(ref);  // a light has no physics: it moves
  light.position[0] = c_position.GetX(), light.position[1] = c_position.GetY(), light.position[2] = c_position.GetZ();
  World("SetPosition").SetLight(ref, light);
}

void CPositionalEntity::SetOrientation(const CQuaternion& c_orientation) {
  m_cOrientation = c_orientation;
  essaim::ArgosRef ref;
  if (SEntityBinding::Find(*this, &ref) && ref.kind != essaim::kArgosLight)
    m_nOrientationSetAt = static_cast<SInt64>(World("SetOrientation").Tick());
}

CEmbodiedEntity::CEmbodiedEntity(CEntity* pc_parent, const std::string& str_id, const CVector3& c_position,
                                 const CQuaternion& c_orientation, bool b_movable)
    : CPositionalEntity(pc_parent, str_id, c_position, c_orientation), m_bMovable(b_movable) {
  m_sOriginAnchor.Id = "origin";
}

const SAnchor& CEmbodiedEntity::GetOriginAnchor() const {
  essaim::ArgosRef ref;
  if (SEntityBinding::Find(*this, &ref)) {
    essaim::ArgosPose pose;
    if (!World("GetOriginAnchor").Pose(ref, &pose))
      THROW_ARGOSEXCEPTION("GetOriginAnchor: \"" << GetRootEntity().GetId() << "\" is not in the space");
    m_sOriginAnchor.Position.Set(pose.x, pose.y, pose.z);
    m_sOriginAnchor.Orientation = FromYaw(pose.yaw);
  } else {
    m_sOriginAnchor.Position = GetPosition();
    m_sOriginAnchor.Orientation = GetOrientation();
  }
  return m_sOriginAnchor;
}

bool CEmbodiedEntity::IsMovable() const {
  essaim::ArgosRef ref;
  return SEntityBinding::Find(*this, &ref) ? World("IsMovable").Movable(ref) : m_bMovable;
}

bool CEmbodiedEntity::MoveTo(const CVector3& c_position, const CQuaternion& c_orientation, bool b_check_only,
                             bool b_ignore_collisions) {
  essaim::ArgosRef ref;
  if (!SEntityBinding::Find(*this, &ref)) {  // not in the space yet: where it will be added
    if (!b_check_only) SetPosition(c_position), SetOrientation(c_orientation);
    return true;
  }
  ref = SEntityBinding::Require(*this, "MoveEntity");
  const essaim::ArgosPose pose{c_position.GetX(), c_position.GetY(), c_position.GetZ(), YawOf(c_orientation)};
  const bool moved = World("MoveEntity").Move(ref, pose, b_check_only, b_ignore_collisions);
  if (moved && !b_check_only) ForgetSetPose();
  return moved;
}

CLEDEntity::CLEDEntity(CLEDEquippedEntity* pc_parent, UInt32 un_index, const CVector3& c_offset, const CColor& c_color)
    : CEntity(pc_parent, pc_parent->GetId() + "." + std::to_string(un_index)),
      m_cEquipped(*pc_parent),
      m_unIndex(un_index),
      m_cOffset(c_offset),
      m_cColor(c_color) {}

CColor CLEDEntity::GetColor() const {
  essaim::ArgosRef ref;
  if (!SEntityBinding::Find(*this, &ref)) return m_cColor;
  const essaim::ArgosRgb c = World("GetColor").Led(SEntityBinding::Require(*this, "GetColor"), m_unIndex);
  return CColor(c.r, c.g, c.b);
}

void CLEDEntity::SetColor(const CColor& c_color) {
  essaim::ArgosRef ref;
  if (!SEntityBinding::Find(*this, &ref)) {
    m_cColor = c_color;
    return;
  }
  World("SetColor").SetLed(SEntityBinding::Require(*this, "SetColor"), m_unIndex, Rgb(c_color));
}

CLEDEquippedEntity::~CLEDEquippedEntity() {
  for (CLEDEntity* led : m_vecLEDs) delete led;
}

void CLEDEquippedEntity::AddLED(const CVector3& c_offset, const CColor& c_color) {
  essaim::ArgosRef ref;
  if (SEntityBinding::Find(*this, &ref))
    THROW_ARGOSEXCEPTION("AddLED: \"" << GetRootEntity().GetId() << "\" is in the space: add LEDs before AddEntity");
  m_vecLEDs.push_back(new CLEDEntity(this, static_cast<UInt32>(m_vecLEDs.size()), c_offset, c_color));
}

CLEDEntity& CLEDEquippedEntity::GetLED(UInt32 un_index) {
  if (un_index >= m_vecLEDs.size())
    THROW_ARGOSEXCEPTION("GetLED(" << un_index << "): \"" << GetRootEntity().GetId() << "\" has " << m_vecLEDs.size()
                                   << " LEDs");
  return *m_vecLEDs[un_index];
}

void CLEDEquippedEntity::SetLEDColor(UInt32 un_index, const CColor& c_color) { GetLED(un_index).SetColor(c_color); }

void CLEDEquippedEntity::SetAllLEDsColors(const CColor& c_color) {
  for (CLEDEntity* led : m_vecLEDs) led->SetColor(c_color);
}

void CLEDEquippedEntity::SetAllLEDsColors(const std::vector<CColor>& vec_colors) {
  if (vec_colors.size() != m_vecLEDs.size())
    THROW_ARGOSEXCEPTION("SetAllLEDsColors: " << vec_colors.size() << " colours for " << m_vecLEDs.size() << " LEDs");
  for (size_t k = 0; k < vec_colors.size(); ++k) m_vecLEDs[k]->SetColor(vec_colors[k]);
}

void CLEDEquippedEntity::AddToMedium(CLEDMedium& c_medium) {
  m_strMedium = c_medium.GetId();
  essaim::ArgosRef ref;
  if (SEntityBinding::Find(*this, &ref))
    World("AddToMedium").SetMedium(SEntityBinding::Require(*this, "AddToMedium"), m_strMedium);
}

namespace {
// Changes a light in the world, or the values it will be added with.
template <typename Change>
void ChangeLight(CLightEntity& light, const char* what, Change change) {
  essaim::ArgosRef ref;
  if (!SEntityBinding::Find(light, &ref)) return;
  ref = SEntityBinding::Require(light, what);
  essaim::ArgosLight l = World(what).Light(ref);
  change(&l);
  World(what).SetLight(ref, l);
}
}  // namespace

CColor CLightEntity::GetColor() const {
  essaim::ArgosRef ref;
  if (!SEntityBinding::Find(*this, &ref)) return m_cColor;
  const essaim::ArgosRgb c = World("GetColor").Light(SEntityBinding::Require(*this, "GetColor")).color;
  return CColor(c.r, c.g, c.b);
}

void CLightEntity::SetColor(const CColor& c_color) {
  m_cColor = c_color;
  ChangeLight(*this, "SetColor", [&](essaim::ArgosLight* l) { l->color = Rgb(c_color); });
}

Real CLightEntity::GetIntensity() const {
  essaim::ArgosRef ref;
  if (!SEntityBinding::Find(*this, &ref)) return m_fIntensity;
  return World("GetIntensity").Light(SEntityBinding::Require(*this, "GetIntensity")).intensity;
}

void CLightEntity::SetIntensity(Real f_intensity) {
  m_fIntensity = f_intensity;
  ChangeLight(*this, "SetIntensity", [&](essaim::ArgosLight* l) { l->intensity = f_intensity; });
}

void CLightEntity::AddToMedium(CLEDMedium& c_medium) {
  m_strMedium = c_medium.GetId();
  ChangeLight(*this, "AddToMedium", [&](essaim::ArgosLight* l) { l->medium = m_strMedium; });
}

CControllableEntity::~CControllableEntity() { delete m_pcController; }

// A robot's C++ controller itself (loop functions cast it to their class), else the wrapper
// of its Lua one.
CCI_Controller& CControllableEntity::GetController() {
  const essaim::ArgosRef ref = SEntityBinding::Require(*this, "GetController");
  if (CCI_Controller* pcCpp = essaim::CurrentController(ref.serial)) return *pcCpp;
  if (!m_pcController) m_pcController = new CLuaController(m_strControllerId, ref.serial);
  return *m_pcController;
}

lua_State* CLuaController::GetLuaState() {
  lua_State* state = World("GetLuaState").LuaState(m_unRobot);
  if (!state) THROW_ARGOSEXCEPTION("GetLuaState: robot " << m_unRobot << "'s controller has no Lua state");
  return state;
}
bool CLuaController::IsOK() { return World("IsOK").ControllerOk(m_unRobot); }

void CFloorEntity::SetChanged() { World("SetChanged").FloorChanged(); }

}  // namespace argos
