#include "app/web_pages.h"

#include <cstddef>

namespace essaim {

extern const char kReplayTemplate[];
extern const std::size_t kReplayTemplate_size;
extern const char kLivePage[];
extern const std::size_t kLivePage_size;
extern const char kArenaViewJs[];
extern const std::size_t kArenaViewJs_size;
extern const char kChartsJs[];
extern const std::size_t kChartsJs_size;

namespace {
void Replace(std::string* page, const std::string& placeholder, const std::string& with) {
  size_t at = page->find(placeholder);
  if (at != std::string::npos) page->replace(at, placeholder.size(), with);
}

std::string WithSharedScripts(std::string page) {
  Replace(&page, "/*@ESSAIM_ARENA_VIEW_JS@*/", std::string(kArenaViewJs, kArenaViewJs_size));
  Replace(&page, "/*@ESSAIM_CHARTS_JS@*/", std::string(kChartsJs, kChartsJs_size));
  return page;
}

// Text inside a <script> element ends at "</": the CSV's column names could hold one.
std::string ScriptSafe(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/')
      out += "<\\";
    else
      out += text[i];
  }
  return out;
}
}  // namespace

std::string ReplayPage(const std::string& recording_base64, const std::string& series_csv) {
  // The recording first: base64 holds no '@', so no placeholder can appear inside it.
  std::string page = WithSharedScripts(std::string(kReplayTemplate, kReplayTemplate_size));
  Replace(&page, "@ESSAIM_RECORDING@", recording_base64);
  Replace(&page, "@ESSAIM_SERIES@", ScriptSafe(series_csv));
  return page;
}

std::string LivePage() { return WithSharedScripts(std::string(kLivePage, kLivePage_size)); }

}  // namespace essaim
