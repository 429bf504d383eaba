#include "argos/api/entity_specs.h"

#include <argos3/plugins/robots/foot-bot/simulator/footbot_entity.h>
#include <argos3/plugins/simulator/entities/box_entity.h>
#include <argos3/plugins/simulator/entities/cylinder_entity.h>
#include <argos3/plugins/simulator/entities/light_entity.h>

#include <cmath>

#include "argos/api/entity_binding.h"
#include "argos/api/session_state.h"

namespace argos {

Real YawOf(const CQuaternion& c_orientation) {
  CRadians z, y, x;
  c_orientation.ToEulerAngles(z, y, x);
  return z.GetValue();
}

CQuaternion FromYaw(Real f_yaw) { return CQuaternion(std::cos(f_yaw / 2), 0, 0, std::sin(f_yaw / 2)); }

namespace {
essaim::ArgosRgb Rgb(const CColor& c) { return {c.GetRed(), c.GetGreen(), c.GetBlue()}; }
CColor Color(const essaim::ArgosRgb& c) { return CColor(c.r, c.g, c.b); }

// The body's pose and LEDs, common to boxes and cylinders.
void FillBody(CEmbodiedEntity& body, CLEDEquippedEntity& leds, essaim::ArgosBody* spec) {
  const SAnchor& anchor = body.GetOriginAnchor();
  spec->pose = {anchor.Position.GetX(), anchor.Position.GetY(), anchor.Position.GetZ(), YawOf(anchor.Orientation)};
  spec->movable = body.IsMovable();
  for (CLEDEntity* led : leds.GetLEDs()) {
    spec->led_offsets.push_back({led->GetOffset().GetX(), led->GetOffset().GetY(), led->GetOffset().GetZ()});
    spec->led_colors.push_back(Rgb(led->GetColor()));
  }
  spec->medium = leds.GetMediumId();
}

bool AddBox(essaim::ArgosWorld& world, CBoxEntity& box, essaim::ArgosRef* ref, std::string* error) {
  essaim::ArgosBody spec;
  spec.id = box.GetId();
  spec.kind = essaim::kArgosBox;
  spec.size[0] = box.GetSize().GetX(), spec.size[1] = box.GetSize().GetY(), spec.size[2] = box.GetSize().GetZ();
  spec.mass = box.GetMass();
  FillBody(box.GetEmbodiedEntity(), box.GetLEDEquippedEntity(), &spec);
  return world.Add(spec, ref, error);
}

bool AddCylinder(essaim::ArgosWorld& world, CCylinderEntity& cylinder, essaim::ArgosRef* ref, std::string* error) {
  essaim::ArgosBody spec;
  spec.id = cylinder.GetId();
  spec.kind = essaim::kArgosCylinder;
  spec.radius = cylinder.GetRadius(), spec.height = cylinder.GetHeight(), spec.mass = cylinder.GetMass();
  FillBody(cylinder.GetEmbodiedEntity(), cylinder.GetLEDEquippedEntity(), &spec);
  return world.Add(spec, ref, error);
}

bool AddLight(essaim::ArgosWorld& world, CLightEntity& light, essaim::ArgosRef* ref, std::string* error) {
  essaim::ArgosLight spec;
  spec.id = light.GetId();
  const CVector3 p = light.GetPosition();
  spec.position[0] = p.GetX(), spec.position[1] = p.GetY(), spec.position[2] = p.GetZ();
  spec.color = Rgb(light.GetColor());
  spec.intensity = light.GetIntensity();
  spec.medium = light.GetMediumId();
  return world.Add(spec, ref, error);
}
bool AddFootBot(essaim::ArgosWorld& world, CFootBotEntity& robot, essaim::ArgosRef* ref, std::string* error) {
  if (!world.Add(SEntityBinding::RobotSpec(robot), ref, error)) return false;
  for (int k = 0; k < world.LedCount(*ref); ++k) robot.GetLEDEquippedEntity().AddLED(CVector3());
  return true;
}
}  // namespace

essaim::ArgosRobot SEntityBinding::RobotSpec(const CFootBotEntity& c_robot) {
  essaim::ArgosRobot spec;
  spec.id = c_robot.GetId();
  spec.controller_id = c_robot.m_strControllerId;
  const SAnchor& anchor = c_robot.m_cEmbodied.GetOriginAnchor();
  spec.pose = {anchor.Position.GetX(), anchor.Position.GetY(), anchor.Position.GetZ(), YawOf(anchor.Orientation)};
  spec.rab_range = c_robot.m_fRabRange;
  spec.rab_data_size = c_robot.m_unRabDataSize;
  spec.camera_aperture = c_robot.m_cOmnicamAperture.GetValue();
  return spec;
}

bool AddToWorld(essaim::ArgosWorld& world, CEntity& c_entity, essaim::ArgosRef* ref, std::string* error) {
  if (auto* box = dynamic_cast<CBoxEntity*>(&c_entity)) return AddBox(world, *box, ref, error);
  if (auto* cylinder = dynamic_cast<CCylinderEntity*>(&c_entity)) return AddCylinder(world, *cylinder, ref, error);
  if (auto* light = dynamic_cast<CLightEntity*>(&c_entity)) return AddLight(world, *light, ref, error);
  if (auto* robot = dynamic_cast<CFootBotEntity*>(&c_entity)) return AddFootBot(world, *robot, ref, error);
  *error = "essaim adds foot-bots, boxes, cylinders and lights only, not a " + c_entity.GetTypeDescription();
  return false;
}

namespace {
CVector3 Position(const essaim::ArgosPose& p) { return CVector3(p.x, p.y, p.z); }

std::unique_ptr<CEntity> MakeBodyWrapper(essaim::ArgosWorld& world, const essaim::ArgosRef& ref) {
  const essaim::ArgosBody b = world.Body(ref);
  essaim::ArgosPose pose;
  world.Pose(ref, &pose);
  CLEDEquippedEntity* leds;
  std::unique_ptr<CEntity> made;
  if (ref.kind == essaim::kArgosBox) {
    auto* box = new CBoxEntity(b.id, Position(pose), FromYaw(pose.yaw), b.movable,
                               CVector3(b.size[0], b.size[1], b.size[2]), b.mass);
    made.reset(box), leds = &box->GetLEDEquippedEntity();
  } else {
    auto* cylinder =
        new CCylinderEntity(b.id, Position(pose), FromYaw(pose.yaw), b.movable, b.radius, b.height, b.mass);
    made.reset(cylinder), leds = &cylinder->GetLEDEquippedEntity();
  }
  for (size_t k = 0; k < b.led_offsets.size(); ++k)
    leds->AddLED(CVector3(b.led_offsets[k][0], b.led_offsets[k][1], b.led_offsets[k][2]), Color(b.led_colors[k]));
  return made;
}
}  // namespace

std::unique_ptr<CEntity> MakeWrapper(essaim::ArgosWorld& world, const essaim::ArgosRef& ref) {
  std::unique_ptr<CEntity> made;
  essaim::ArgosPose pose;
  world.Pose(ref, &pose);
  if (ref.kind == essaim::kArgosFootBot) {
    auto* robot = new CFootBotEntity(world.Id(ref), world.ControllerId(ref.serial), Position(pose), FromYaw(pose.yaw));
    made.reset(robot);
    for (int k = 0; k < world.LedCount(ref); ++k) robot->GetLEDEquippedEntity().AddLED(CVector3());
  } else if (ref.kind == essaim::kArgosLight) {
    const essaim::ArgosLight l = world.Light(ref);
    auto* light =
        new CLightEntity(l.id, CVector3(l.position[0], l.position[1], l.position[2]), Color(l.color), l.intensity);
    made.reset(light);
  } else {
    made = MakeBodyWrapper(world, ref);
  }
  SEntityBinding::Bind(*made, ref);
  return made;
}

CEntity& SEntityBinding::Wrapper(CSpace& c_space, const essaim::ArgosRef& ref) {
  std::unique_ptr<CEntity>& slot = c_space.m_psEntities->wrappers[{ref.kind, ref.serial}];
  if (!slot) slot = MakeWrapper(*essaim::RequireSession("an entity").world, ref);
  return *slot;
}

}  // namespace argos
