// Inside the ARGoS API library: the labels REGISTER_LOOP_FUNCTIONS and REGISTER_CONTROLLER
// registered, each with the library that did. Loaded libraries stay for the process, so a
// label is looked up among the libraries of one experiment only, the last of them that
// registers it winning, as ARGoS's factory keeps the last one loaded.
#pragma once
#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <string>
#include <vector>

#include "argos/argos_session.h"

namespace essaim {

/// The real path of the file holding `address` (a creator function); "" when unknown.
inline std::string LibraryOf(const void* address) {
  Dl_info info{};
  if (!dladdr(address, &info) || !info.dli_fname) return "";
  char* real = realpath(info.dli_fname, nullptr);
  std::string library = real ? real : info.dli_fname;
  std::free(real);
  return library;
}

/// What a registry's messages call its kind: "loop functions" and REGISTER_LOOP_FUNCTIONS.
struct ArgosRegistryWords {
  const char* kind;
  const char* macro;
  const char* looked_up;  // where the experiment's libraries come from
};

template <typename Creator>
class ArgosRegistry {
 public:
  struct Entry {
    std::string label;
    Creator creator;
    int api_version;
    std::string library;  // real path of the file holding `creator`
  };
  explicit ArgosRegistry(ArgosRegistryWords words) : words_(words) {}

  // Runs from a library's static constructors, inside its dlopen; dladdr names the file.
  void Add(const char* label, Creator creator, int api_version) {
    std::string library = LibraryOf(reinterpret_cast<const void*>(creator));
    std::lock_guard<std::mutex> hold(lock_);
    entries_.push_back({label, creator, api_version, std::move(library)});
  }
  std::vector<ArgosRegistration> List() {
    std::vector<ArgosRegistration> out;
    std::lock_guard<std::mutex> hold(lock_);
    for (const Entry& e : entries_) out.push_back({e.label, e.api_version, e.library});
    return out;
  }
  /// The registration of `label` among `libraries`: the last library's; a label twice in
  /// one library is an error. The entry stays where it is (a deque) while others register.
  const Entry* Find(const std::vector<std::string>& libraries, const std::string& label, std::string* error) {
    std::lock_guard<std::mutex> hold(lock_);
    const Entry* found = nullptr;
    for (const std::string& library : libraries) {
      const Entry* here = nullptr;
      for (const Entry& e : entries_) {
        if (e.library != library || e.label != label) continue;
        if (here)
          return *error = "label '" + label + "' is registered twice in " + library + " (" + words_.macro +
                          "): give each class its own label",
                 nullptr;
        here = &e;
      }
      if (here) found = here;
    }
    if (!found) *error = NotFound(libraries, label);
    return found;
  }

 private:
  // Why `label` is not found: the labels `libraries` register, and a library outside them
  // that registers it (a library the one named depends on, or another experiment's).
  std::string NotFound(const std::vector<std::string>& libraries, const std::string& label) const {
    std::string labels, elsewhere;
    for (const Entry& e : entries_) {
      if (std::find(libraries.begin(), libraries.end(), e.library) != libraries.end())
        labels += (labels.empty() ? "" : ", ") + e.label;
      else if (e.label == label && elsewhere.empty())
        elsewhere = "; " + e.library + " registers it, but this experiment's " + words_.kind + " are looked up in " +
                    words_.looked_up + " only";
    }
    return std::string("no ") + words_.kind + " registered as '" + label + "' (" + words_.macro +
           ") in the libraries loaded" +
           (labels.empty() ? std::string(": none registers any") : "; registered: " + labels) + elsewhere;
  }

  ArgosRegistryWords words_;
  std::mutex lock_;
  std::deque<Entry> entries_;
};

}  // namespace essaim
