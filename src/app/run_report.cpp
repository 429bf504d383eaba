#include "app/run_report.h"

#include "core/error_list.h"

namespace essaim {

std::string FormatUnreadParams(const std::vector<UnreadParam>& unread, bool as_errors) {
  ErrorList list;
  for (const UnreadParam& u : unread) {
    std::string text = std::string(as_errors ? "error" : "warning") + ": parameter '" + u.key + "'";
    if (!u.set_by.empty()) text += " (--set " + u.set_by + ")";
    text += " is never read by " + (u.script.empty() ? std::string("the script") : u.script);
    if (!u.did_you_mean.empty()) text += "; did you mean '" + u.did_you_mean + "'?";
    list.Add(u.loc.file, u.loc.line, u.loc.element, text);
  }
  return list.Format();
}

}  // namespace essaim
