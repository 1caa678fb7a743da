#pragma once
// The code kinds we mark, by the names the command line uses, and what each needs around it.
#include <string_view>
#include <vector>

namespace mark {

enum class Symbology { datamatrix, gs1_datamatrix, qr, code128, gs1_128 };

std::string_view to_string(Symbology s);
// "datamatrix", "gs1-datamatrix", "qr", "code128", "gs1-128"; throws InputError naming the
// value and the choices otherwise.
Symbology parse_symbology(std::string_view name);
std::vector<std::string_view> symbology_names();

bool is_gs1(Symbology s);
bool is_linear(Symbology s);  // Code 128 and GS1-128: bars, one row
// Quiet zone in modules on every side (left and right only for linear codes): ISO/IEC 16022
// (Data Matrix) 1, ISO/IEC 18004 (QR) 4, ISO/IEC 15417 (Code 128) 10.
int quiet_zone_modules(Symbology s);

}  // namespace mark
