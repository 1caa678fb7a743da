#include "marker/station/station_commands.hpp"

#include <cctype>
#include <cstdio>

namespace mark {

std::string reply_value(std::string_view value) {
  bool plain = !value.empty();
  for (unsigned char c : value)
    if (c <= ' ' || c == '"' || c == '\\' || c == '=' || c == 127) plain = false;
  if (plain) return std::string(value);
  std::string s = "\"";
  for (unsigned char c : value) {
    if (c == '"' || c == '\\') s.append(1, '\\').append(1, static_cast<char>(c));
    else if (c == '\n') s += "\\n";
    else if (c < ' ' || c == 127) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      s += hex;
    } else s += static_cast<char>(c);
  }
  return s + "\"";
}

std::string part_reply(const PartResult& part) {
  std::string s = "id=" + std::to_string(part.mark_id) + " outcome=" + std::string(part.outcome_name());
  for (const auto& [name, value] : part.serials) s += " " + name + "=" + std::to_string(value);
  s += " text=" + reply_value(part.text());
  s += " mark_time_s=" + std::to_string(part.mark_time_s);
  if (!part.message.empty()) s += " message=" + reply_value(part.message);
  if (!part.recorded.stored)
    s += part.recorded.journaled ? " recorded=journal" : " recorded=no";
  return s;
}

namespace {

std::string ok(std::string_view rest = {}) { return rest.empty() ? "OK" : "OK " + std::string(rest); }
std::string err(const StationError& e) {
  std::string m = e.message;
  for (char& c : m)
    if (c == '\n' || c == '\r') c = ' ';
  return "ERR " + e.code + " " + m;
}
std::string err(std::string code, std::string message) { return err(StationError{std::move(code), std::move(message)}); }

std::string status_reply(const StationStatus& s) {
  std::string r = "state=" + std::string(to_string(s.state)) + " job=" + reply_value(s.job) +
                  " parts=" + std::to_string(s.parts);
  for (const auto& [outcome, n] : s.outcomes) r += " " + outcome + "=" + std::to_string(n);
  if (s.last) r += " last_id=" + std::to_string(s.last->mark_id) + " last_outcome=" + std::string(to_string(s.last->outcome));
  if (!s.error.empty()) r += " error=" + reply_value(s.error);
  return r;
}

// The first word (upper-cased) and the rest of the line after one space.
std::pair<std::string, std::string_view> split(std::string_view line) {
  const std::size_t sp = line.find(' ');
  std::string verb(line.substr(0, sp));
  for (char& c : verb) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  std::string_view rest = sp == std::string_view::npos ? std::string_view{} : line.substr(sp + 1);
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  return {verb, rest};
}

constexpr std::string_view kCommands =
    "LOAD <job>, SET <var> <value>, MARK, MARK ASYNC, STATUS, ABORT, PAUSE, RESUME, RESET, SERIAL <counter>, PREVIEW";

}  // namespace

std::string station_command(Station& station, std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.size() >= kStationLineMax)
    return err("toolong", "a command line has at most " + std::to_string(kStationLineMax - 1) + " bytes");
  for (unsigned char c : line)
    if (c < ' ' || c == 127) return err("syntax", "control characters are not allowed in a command line");
  const auto [verb, rest] = split(line);
  const auto no_args = [&, &rest = rest, &verb = verb]() -> std::optional<std::string> {
    if (!rest.empty()) return err("syntax", verb + " takes no argument (got \"" + std::string(rest) + "\")");
    return std::nullopt;
  };
  if (verb == "MARK") {
    if (rest.empty()) {
      const MarkAttempt a = station.mark();
      if (a.part) {
        const std::string fields = part_reply(*a.part);
        if (a.part->good()) return ok(fields);
        return "ERR " + std::string(a.part->outcome_name()) + " " + fields;
      }
      return err(*a.error);
    }
    std::string mode(rest);
    for (char& c : mode) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (mode != "ASYNC") return err("syntax", "MARK takes nothing or ASYNC (got \"" + std::string(rest) + "\")");
    if (auto e = station.mark_async()) return err(*e);
    return ok("started");
  }
  if (verb == "STATUS") {
    if (auto e = no_args()) return *e;
    return ok(status_reply(station.status()));
  }
  if (verb == "ABORT") {
    if (auto e = no_args()) return *e;
    return ok("laser_off state_was=" + std::string(to_string(station.abort())));
  }
  if (verb == "PAUSE" || verb == "RESUME" || verb == "RESET") {
    if (auto e = no_args()) return *e;
    const auto e = verb == "PAUSE" ? station.pause() : verb == "RESUME" ? station.resume() : station.reset();
    if (e) return err(*e);
    return ok("state=" + std::string(to_string(station.status().state)));
  }
  if (verb == "SET") {
    const std::size_t sp = rest.find(' ');
    if (rest.empty() || sp == std::string_view::npos)
      return err("syntax", "SET takes a variable name and a value: SET <var> <value>");
    const std::string name(rest.substr(0, sp));
    const std::string value(rest.substr(sp + 1));
    if (auto e = station.set_variable(name, value)) return err(*e);
    return ok(name + "=" + reply_value(value));
  }
  if (verb == "LOAD") {
    if (rest.empty()) return err("syntax", "LOAD takes a job file: LOAD <job>");
    if (auto e = station.load(std::string(rest))) return err(*e);
    return ok("job=" + reply_value(station.status().job));
  }
  if (verb == "SERIAL") {
    if (rest.empty() || rest.find(' ') != std::string_view::npos)
      return err("syntax", "SERIAL takes one counter name: SERIAL <counter>");
    std::optional<std::int64_t> next;
    if (auto e = station.next_serial(std::string(rest), next)) return err(*e);
    return ok(std::string(rest) + "=" + (next ? std::to_string(*next) : std::string("stopped")));
  }
  if (verb == "PREVIEW") {
    if (auto e = no_args()) return *e;
    std::vector<ObjectText> texts;
    std::map<std::string, std::int64_t> serials;
    if (auto e = station.preview(texts, serials)) return err(*e);
    std::string r;
    for (const auto& [name, value] : serials) r += name + "=" + std::to_string(value) + " ";
    std::string text;
    for (const ObjectText& t : texts) text += (text.empty() ? "" : "\n") + t.text;
    return ok(r + "text=" + reply_value(text));
  }
  if (verb.empty()) return err("syntax", "empty command line; commands: " + std::string(kCommands));
  return err("unknown", "no command \"" + std::string(verb.substr(0, 64)) + "\"; commands: " + std::string(kCommands));
}

}  // namespace mark
