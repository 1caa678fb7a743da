#pragma once
// The operator page (GET /): the station's state, the last part (text, serial values, outcome),
// the next mark's text, the last 50 marks and Mark / Abort / Pause / Reset buttons. Plain HTML and a little JavaScript,
// compiled into the binary: no files to install, nothing fetched from anywhere but the station.
#include <string_view>

namespace mark {

std::string_view operator_page_html();

}  // namespace mark
