#include "marker/codes/symbology.hpp"

#include <string>

#include "base/error.hpp"

namespace mark {
namespace {

struct Entry {
  Symbology symbology;
  std::string_view name;
};
constexpr Entry kNames[] = {{Symbology::datamatrix, "datamatrix"},
                            {Symbology::gs1_datamatrix, "gs1-datamatrix"},
                            {Symbology::qr, "qr"},
                            {Symbology::code128, "code128"},
                            {Symbology::gs1_128, "gs1-128"}};

}  // namespace

std::string_view to_string(Symbology s) {
  for (const Entry& e : kNames)
    if (e.symbology == s) return e.name;
  return "?";
}

std::vector<std::string_view> symbology_names() {
  std::vector<std::string_view> out;
  for (const Entry& e : kNames) out.push_back(e.name);
  return out;
}

Symbology parse_symbology(std::string_view name) {
  for (const Entry& e : kNames)
    if (e.name == name) return e.symbology;
  std::string all;
  for (const Entry& e : kNames) all += (all.empty() ? "" : ", ") + std::string(e.name);
  throw InputError("symbology '" + std::string(name) + "' is not one of " + all);
}

bool is_gs1(Symbology s) { return s == Symbology::gs1_datamatrix || s == Symbology::gs1_128; }
bool is_linear(Symbology s) { return s == Symbology::code128 || s == Symbology::gs1_128; }

int quiet_zone_modules(Symbology s) {
  switch (s) {
    case Symbology::datamatrix:
    case Symbology::gs1_datamatrix: return 1;
    case Symbology::qr: return 4;
    case Symbology::code128:
    case Symbology::gs1_128: return 10;
  }
  return 1;
}

}  // namespace mark
