// The pages essaim serves or writes: replay.html and the live page of `essaim serve`. Both
// embed the same arena drawing (arena_view.js) and charts (charts.js).
#pragma once
#include <string>

namespace essaim {

/// The replay page with a recording (base64) and the run's timeseries.csv ("" : none).
std::string ReplayPage(const std::string& recording_base64, const std::string& series_csv);
/// The live page.
std::string LivePage();

}  // namespace essaim
