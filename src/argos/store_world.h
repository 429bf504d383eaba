// The ARGoS API library's view of a run (ArgosWorld) over the World's EntityStore, the
// one interface the Lua loop functions reach the world through too; plus the robots'
// controllers (for GetLuaState) and the loop functions' log buffer.
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "argos/argos_world.h"
#include "devices/entity_store.h"
#include "lua/robot/lua_controller.h"
#include "model/model.h"

namespace essaim {

class StoreWorld : public ArgosWorld {
 public:
  StoreWorld(const Model& model, EntityStore* entities, std::vector<std::unique_ptr<RobotController>>* controllers)
      : model_(model), entities_(*entities), controllers_(*controllers) {}
  void SetTick(uint64_t tick) { tick_ = tick; }
  /// Lines logged, "<O or E><text>\n" each (sim's FlushLog empties it), with those the
  /// libraries logged outside any hook since (at load, from a thread of their own).
  std::string& LogBuffer();
  /// Whether SetChanged() was called since the last call.
  bool TakeFloorChanged() { return std::exchange(floor_changed_, false); }

  uint64_t Tick() const override { return tick_; }
  uint64_t Seed() const override { return model_.experiment.seed; }
  uint64_t LengthTicks() const override { return model_.experiment.length_ticks; }
  double TickLength() const override { return model_.experiment.TickLength(); }
  void Arena(double size[3], double center[3]) const override;
  std::vector<std::string> LedMedia() const override;
  std::vector<ArgosRef> Entities(int kind) const override;
  uint64_t LayoutVersion() const override;
  bool Live(const ArgosRef& e) const override { return entities_.IndexOf(Ref(e)) >= 0; }
  std::string Id(const ArgosRef& e) const override { return entities_.IdOf(Ref(e)); }
  bool Pose(const ArgosRef& e, ArgosPose* pose) const override;
  bool Movable(const ArgosRef& e) const override { return entities_.Movable(Ref(e), entities_.IndexOf(Ref(e))); }
  bool Move(const ArgosRef& e, const ArgosPose& pose, bool check_only, bool ignore_collisions) override;
  ArgosBody Body(const ArgosRef& e) const override;
  int LedCount(const ArgosRef& e) const override { return entities_.LedCount(Ref(e), entities_.IndexOf(Ref(e))); }
  ArgosRgb Led(const ArgosRef& e, int k) const override;
  void SetLed(const ArgosRef& e, int k, const ArgosRgb& color) override;
  void SetMedium(const ArgosRef& e, const std::string& medium) override;
  ArgosLight Light(const ArgosRef& e) const override;
  void SetLight(const ArgosRef& e, const ArgosLight& light) override;
  bool Add(const ArgosBody& body, ArgosRef* added, std::string* error) override;
  bool Add(const ArgosLight& light, ArgosRef* added, std::string* error) override;
  bool Add(const ArgosRobot& robot, ArgosRef* added, std::string* error) override;
  bool Remove(const ArgosRef& e) override { return entities_.Remove(Ref(e)); }
  std::string ControllerId(uint32_t robot) const override { return model_.robots[robot].controller_id; }
  lua_State* LuaState(uint32_t robot) override;
  bool ControllerOk(uint32_t robot) const override { return entities_.Robot(static_cast<int>(robot)).controller_ok; }
  void Log(bool error, const std::string& line) override;
  void FloorChanged() override { floor_changed_ = true; }

 private:
  static EntityRef Ref(const ArgosRef& e) { return {static_cast<EntityKind>(e.kind), e.serial}; }
  /// Whether entity `e` at `pose` would overlap a robot or a box or cylinder other than itself.
  bool Overlaps(const ArgosRef& e, const Pose2& pose) const;
  std::string MediumProblem(const std::string& medium) const;
  const Model& model_;
  EntityStore& entities_;
  std::vector<std::unique_ptr<RobotController>>& controllers_;
  uint64_t tick_ = 0;
  std::string log_;
  bool floor_changed_ = false;
};

}  // namespace essaim
