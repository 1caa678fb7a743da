#include "marker/cli/unread_options.hpp"

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"

namespace mark::cli {

bool given(const CLI::App& app, const SettingRef& setting, std::string_view prefix) {
  const SettingName& n = name_of(setting);
  if (n.flag.empty()) return false;
  const CLI::Option* o = app.get_option_no_throw(flag_of(n, prefix));
  // A toggle on unless turned off counts its --no- form too (one option, two names).
  return o && o->count() > 0;
}

void refuse_unread(const CLI::App& app, std::span<const SettingRef> settings,
                   const std::function<std::optional<std::string>(const SettingRef&)>& unread,
                   std::string_view prefix) {
  for (const SettingRef& s : settings)
    if (given(app, s, prefix))
      if (const std::optional<std::string> why = unread(s)) {
        std::string typed = flag_of(name_of(s), prefix);
        // A toggle on by default was given by its --no- form when it reads off: name that one.
        if (const auto* t = std::get_if<const Toggle*>(&s); t && (*t)->on && !app.get_option(typed)->as<bool>())
          typed = "--no-" + typed.substr(2);
        throw InputError(typed + " does not apply: " + *why);
      }
}

void refuse_unread(const CLI::App& app, std::span<const SettingRef> settings, bool read, std::string_view why,
                   std::string_view prefix) {
  if (read) return;
  refuse_unread(app, settings, [&](const SettingRef&) { return std::optional<std::string>(why); }, prefix);
}

}  // namespace mark::cli
