// The session's hooks, guarded: the session is current while a hook runs, and what it
// throws comes back as an error message with the file and line it was thrown from.
#include <argos3/core/simulator/loop_functions.h>

#include <exception>
#include <functional>

#include "argos/api/registry.h"
#include "argos/api/session_state.h"
#include "argos/argos_session.h"

namespace essaim {

namespace {
thread_local ArgosSession::State* current_session = nullptr;

ArgosRegistry<argos::TLoopFunctionsCreator>& Registry() {
  static ArgosRegistry<argos::TLoopFunctionsCreator> registry(
      {"loop functions", "REGISTER_LOOP_FUNCTIONS",
       "the library it names (or, with label alone, in ARGOS_PLUGIN_PATH's)"});
  return registry;
}

// Runs `body` with `state` current; an exception becomes `*error`, prefixed with `hook`.
bool Guarded(ArgosSession::State* state, const char* hook, const std::function<void()>& body, std::string* error) {
  ArgosSession::State* before = current_session;
  current_session = state;
  state->configuration_error = false;
  bool ok = false;
  try {
    body();
    ok = true;
  } catch (const argos::CARGoSException& e) {
    *error = std::string("loop functions (") + hook + "): " + DescribeException(e);
    state->configuration_error = e.IsConfigurationError();
  } catch (const std::exception& e) {
    *error = std::string("loop functions (") + hook + "): " + e.what();
  } catch (...) {
    *error = std::string("loop functions (") + hook + "): an exception that is not a std::exception";
  }
  argos::LOG.Flush();
  argos::LOGERR.Flush();
  current_session = before;
  return ok;
}

const char* HookName(ArgosHook hook) {
  switch (hook) {
    case ArgosHook::Reset:
      return "Reset";
    case ArgosHook::Destroy:
      return "Destroy";
    case ArgosHook::PreStep:
      return "PreStep";
    case ArgosHook::PostStep:
      return "PostStep";
    default:
      return "PostExperiment";
  }
}
}  // namespace

ArgosSession::State* CurrentSession() { return current_session; }

ArgosSession::State* SetCurrentSession(ArgosSession::State* state) {
  ArgosSession::State* before = current_session;
  current_session = state;
  return before;
}

std::string DescribeException(const argos::CARGoSException& e) {
  if (e.GetFile().empty()) return e.what();
  return e.GetFile() + ":" + std::to_string(e.GetLine()) + ": " + e.what();
}

ArgosSession::State& RequireSession(const char* what) {
  if (!current_session)
    THROW_ARGOSEXCEPTION(what << ": no experiment is running (only loop functions' hooks may call it)");
  return *current_session;
}

std::vector<ArgosRegistration> ArgosRegisteredLabels() { return Registry().List(); }

int ArgosApiVersion() { return ARGOS_ESSAIM_API_VERSION; }

ArgosSession::ArgosSession(ArgosWorld* world) : state_(std::make_unique<State>(world)) {
  for (const std::string& id : world->LedMedia()) state_->media[id] = std::make_unique<argos::CLEDMedium>(id);
  // CRandom's "argos" category, seeded with the experiment's seed as ARGoS's is.
  state_->rng_categories.emplace("argos", static_cast<argos::UInt32>(world->Seed()));
  argos::CPhysicsEngine::SetSimulationClockTick(world->TickLength());
}

ArgosSession::~ArgosSession() {
  // Robots' controllers go first (one may hold a reference to the loop functions). The loop
  // functions' destructor may still reach the space: it runs with the session current.
  for (uint32_t robot = 0; robot < state_->controllers.size(); ++robot) DeleteController(robot);
  std::string ignored;
  Guarded(
      state_.get(), "destructor", [&] { state_->loop_functions.reset(); }, &ignored);
}

bool ArgosSession::Create(const std::vector<std::string>& libraries, const std::string& label, std::string* error) {
  const auto* found = Registry().Find(libraries, label, error);
  if (!found) return false;
  if (found->api_version != ARGOS_ESSAIM_API_VERSION) {
    *error = "loop functions '" + label + "' were built for essaim's ARGoS API version " +
             std::to_string(found->api_version) + ", this essaim provides version " +
             std::to_string(ARGOS_ESSAIM_API_VERSION) + ": rebuild the library against this essaim";
    return false;
  }
  return Guarded(
      state_.get(), "constructor", [&] { state_->loop_functions.reset(found->creator()); }, error);
}

bool ArgosSession::Init(ticpp::Element& tree, std::string* error) {
  return Guarded(
      state_.get(), "Init", [&] { state_->loop_functions->Init(tree); }, error);
}

bool ArgosSession::Run(ArgosHook hook, std::string* error) {
  argos::CLoopFunctions& lf = *state_->loop_functions;
  return Guarded(
      state_.get(), HookName(hook),
      [&] {
        switch (hook) {
          case ArgosHook::Reset:
            return lf.Reset();
          case ArgosHook::Destroy:
            return lf.Destroy();
          case ArgosHook::PreStep:
            return lf.PreStep();
          case ArgosHook::PostStep:
            return lf.PostStep();
          case ArgosHook::PostExperiment:
            return lf.PostExperiment();
        }
      },
      error);
}

bool ArgosSession::LastErrorIsConfiguration() const { return state_->configuration_error; }

bool ArgosSession::IsExperimentFinished(bool* finished, std::string* error) {
  return Guarded(
      state_.get(), "IsExperimentFinished", [&] { *finished = state_->loop_functions->IsExperimentFinished(); }, error);
}

bool ArgosSession::FloorColor(double x, double y, ArgosRgb* color, std::string* error) {
  return Guarded(
      state_.get(), "GetFloorColor",
      [&] {
        const argos::CColor c = state_->loop_functions->GetFloorColor(argos::CVector2(x, y));
        *color = {c.GetRed(), c.GetGreen(), c.GetBlue()};
      },
      error);
}

}  // namespace essaim

namespace argos {
bool RegisterLoopFunctions(const char* str_label, TLoopFunctionsCreator pf_creator, int n_api_version) {
  essaim::Registry().Add(str_label, pf_creator, n_api_version);
  return true;
}
}  // namespace argos
