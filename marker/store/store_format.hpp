#pragma once
// The serial store's format names, one list for every backend (SQLite, PostgreSQL): a store
// names its format in its meta table, and a program reads the formats it knows and refuses the
// rest rather than guess at tables it does not know.
#include <string>

#include "marker/store/store_error.hpp"

namespace mark {

inline constexpr const char* kStoreFormat1 = "marker-store/1";
inline constexpr const char* kStoreFormat2 = "marker-store/2";  // marked texts, data rows, reasons, notes

// 1 or 2 for a format this program reads; a StoreError naming the store and its format otherwise.
inline int store_format_version(const std::string& store, const std::string& format) {
  if (format == kStoreFormat2) return 2;
  if (format == kStoreFormat1) return 1;
  throw StoreError("serial store " + store + " has format '" + format + "', this program reads " + kStoreFormat1 +
                   " and " + kStoreFormat2);
}

}  // namespace mark
