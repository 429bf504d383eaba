#include "sim/stepping.h"

namespace essaim {

Stepping& ThisThreadStepping() {
  static thread_local Stepping stepping;
  return stepping;
}

}  // namespace essaim
