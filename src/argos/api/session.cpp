// The session's hooks, guarded: the session is current while a hook runs, and what it
// throws comes back as an error message with the file and line it was thrown from.
#include <argos3/core/simulator/loop_functions.h>
#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>

#include "argos/api/session_state.h"
#include "argos/argos_session.h"

namespace essaim {

namespace {
thread_local ArgosSession::State* current_session = nullptr;

// A REGISTER_LOOP_FUNCTIONS, with the library that made it: loaded libraries stay for the
// process, so labels are looked up among the libraries of one experiment only.
struct Registration {
  std::string label;
  argos::TLoopFunctionsCreator creator;
  int api_version;
  std::string library;  // real path of the file holding `creator`
};
// A deque: a registration found stays where it is while other libraries register theirs
// (a Python thread may load an experiment while another makes its loop functions).
std::deque<Registration>& Registry() {
  static std::deque<Registration> registry;
  return registry;
}
std::mutex registry_lock;

std::string Describe(const argos::CARGoSException& e) {
  if (e.GetFile().empty()) return e.what();
  return e.GetFile() + ":" + std::to_string(e.GetLine()) + ": " + e.what();
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
    *error = std::string("loop functions (") + hook + "): " + Describe(e);
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

ArgosSession::State& RequireSession(const char* what) {
  if (!current_session)
    THROW_ARGOSEXCEPTION(what << ": no experiment is running (only loop functions' hooks may call it)");
  return *current_session;
}

std::vector<ArgosRegistration> ArgosRegisteredLabels() {
  std::vector<ArgosRegistration> out;
  std::lock_guard<std::mutex> lock(registry_lock);
  for (const Registration& r : Registry()) out.push_back({r.label, r.api_version, r.library});
  return out;
}

int ArgosApiVersion() { return ARGOS_ESSAIM_API_VERSION; }

ArgosSession::ArgosSession(ArgosWorld* world) : state_(std::make_unique<State>(world)) {
  for (const std::string& id : world->LedMedia()) state_->media[id] = std::make_unique<argos::CLEDMedium>(id);
}

ArgosSession::~ArgosSession() {
  // The loop functions' destructor may still reach the space: it runs with the session current.
  std::string ignored;
  Guarded(
      state_.get(), "destructor", [&] { state_->loop_functions.reset(); }, &ignored);
}

namespace {
// Why `label` is not found: the labels `libraries` register, and a library outside them that
// registers it (a library the one named depends on, or another experiment's).
std::string NotFound(const std::vector<std::string>& libraries, const std::string& label) {
  std::string labels, elsewhere;
  for (const Registration& r : Registry()) {
    if (std::find(libraries.begin(), libraries.end(), r.library) != libraries.end())
      labels += (labels.empty() ? "" : ", ") + r.label;
    else if (r.label == label && elsewhere.empty())
      elsewhere = "; " + r.library +
                  " registers it, but this experiment's loop functions are looked up in the "
                  "library it names (or, with label alone, in ARGOS_PLUGIN_PATH's) only";
  }
  return "no loop functions registered as '" + label + "' (REGISTER_LOOP_FUNCTIONS) in the libraries loaded" +
         (labels.empty() ? std::string(": none registers any") : "; registered: " + labels) + elsewhere;
}

// The registration of `label` among `libraries`: the last library's, as ARGoS's factory keeps
// the last one loaded; a label twice in one library is an error.
const Registration* Find(const std::vector<std::string>& libraries, const std::string& label, std::string* error) {
  std::lock_guard<std::mutex> lock(registry_lock);
  const Registration* found = nullptr;
  for (const std::string& library : libraries) {
    const Registration* here = nullptr;
    for (const Registration& r : Registry()) {
      if (r.library != library || r.label != label) continue;
      if (here)
        return *error = "label '" + label + "' is registered twice in " + library +
                        " (REGISTER_LOOP_FUNCTIONS): give each class its own label",
               nullptr;
      here = &r;
    }
    if (here) found = here;
  }
  if (!found) *error = NotFound(libraries, label);
  return found;
}
}  // namespace

bool ArgosSession::Create(const std::vector<std::string>& libraries, const std::string& label, std::string* error) {
  const Registration* found = Find(libraries, label, error);
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
// Runs from the library's static constructors, inside its dlopen; dladdr names the file.
bool RegisterLoopFunctions(const char* str_label, TLoopFunctionsCreator pf_creator, int n_api_version) {
  Dl_info info{};
  std::string library;
  if (dladdr(reinterpret_cast<void*>(pf_creator), &info) && info.dli_fname) {
    char* real = realpath(info.dli_fname, nullptr);
    library = real ? real : info.dli_fname;
    std::free(real);
  }
  std::lock_guard<std::mutex> lock(essaim::registry_lock);
  essaim::Registry().push_back({str_label, pf_creator, n_api_version, library});
  return true;
}
}  // namespace argos
