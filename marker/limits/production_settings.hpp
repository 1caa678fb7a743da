#pragma once
// The settings of production: a job's objects and its variable text, its serial counters
// (`marker job new`'s options and a job file's keys), and the run of `marker mark --job`, the
// serial store's administration and its log (one declaration each, setting.hpp). Counter values
// cover the whole signed 64-bit range the store keeps.
#include <cstdint>

#include "marker/limits/code_settings.hpp"
#include "marker/limits/setting.hpp"
#include "marker/limits/store_limits.hpp"

namespace mark {

// What each object of a job holds besides its layout (layout_settings.hpp) or code (code_settings.hpp).
inline constexpr Text kObjectName{
    {"--name", "name", "the object's name (unique in the job)"}, "text", "`text`; a job file: required"};
inline constexpr Text kObjectPen{
    {"--pen", "pen", "the pen the object is marked with: a name from \"pens\""}, "default",
    "`default`; a job file: the only pen"};
inline constexpr Text kTemplate{
    {"--text", "template",
     "the text (a code: its data) with fields in braces: {serial}, {date:%y%j}, {var:lot}, {shift}"},
    {}, "required"};

// What the object's mark must be to count as good (marker/job/mark_requirement.hpp): judged on the
// simulator before the part fires (short of it: refused, nothing consumed) and on the part as
// marked (short of it: rejected, its numbers void).
inline constexpr Choice kRequireQuality{
    {"--require-quality", "require.quality",
     "the least quality class the simulator must predict, and the mark reach (refused before firing)"},
    "high, good", {}, "none"};
inline constexpr Choice kRequireGrade{
    {"--require-grade", "require.code_grade",
     "the least grade every code must read at (ISO/IEC TR 29158; `mark`: refused before firing, `code`: exit 2)"},
    "A, B, C, D", {}, "none"};
inline constexpr Choice kRequireCode{
    {"", "require.code",
     "every code must read back to its data (always so; the key says it in the file)"},
    "read", {}, "read"};

// Objects laid over each other on purpose: the clearance check (marker/production/object_clearance.*)
// lets these pairs' inks touch. Never a code's quiet zone: a reader needs it bare whatever the job says.
inline constexpr Text kObjectOverlaps{
    {"", "overlaps",
     "the objects whose ink this one's may touch on purpose (a frame around a text, a stroke marked twice): a list of "
     "their names, text objects only"},
    {}, "none"};

inline constexpr SettingRef kObjectSettingList[] = {&kObjectName,     &kObjectPen,    &kTemplate,    &kObjectOverlaps,
                                                    &kRequireQuality, &kRequireGrade, &kRequireCode};
inline constexpr SettingTable kObjectSettings{"object", "Every object", "objects[]", kObjectSettingList};

// `marker job new --code`: a code object (named `code`, on the text's pen) beside the text; the
// file holds it under the code table's keys (code_settings.hpp).
inline constexpr Text kNewCode{
    {"--code", "",
     "add a code object: SYMBOLOGY:DATA, SYMBOLOGY datamatrix, gs1-datamatrix, qr, code128 or gs1-128, DATA a "
     "template like --text's"},
    {}, "none"};
inline constexpr Quantity kNewCodeModule{{"--code-module", "", "the code's module size"}, {0.01, 20, "mm"}, 0.25};
inline constexpr Quantity kNewCodeX{
    {"--code-x", "", "the code's centre x (field frame)"}, kCodePositionBounds, {},
    "beside the text's fixed end: left of a left-aligned text, right of a right-aligned one; its quiet zone "
    "a spot diameter plus 10 % of the text height clear of the text"};
inline constexpr Quantity kNewCodeY{
    {"--code-y", "", "the code's centre y (field frame)"}, kCodePositionBounds, {},
    "the text's middle; below a centred text"};
inline constexpr SettingRef kNewCodeSettingList[] = {&kNewCode, &kNewCodeModule, &kNewCodeX, &kNewCodeY};
inline constexpr SettingTable kNewCodeSettings{"new-code", "job new: a code beside the text", "", kNewCodeSettingList};

// The job's variable text: when, which shift, which variables.
inline constexpr Text kTimeZone{
    {"--time-zone", "time_zone",
     "zone of {date}, {shift} and counter resets: local, UTC or an IANA name (Europe/Berlin)"},
    "local"};
inline constexpr Text kShifts{
    {"--shifts", "shifts",
     "shift codes and start times A=06:00,B=14:00,C=22:00 (a job file: [{\"code\": \"A\", \"start\": \"06:00\"}, "
     "…]); a shift runs to the next one's start, the night shift belongs to the day it started"},
    {}, "none"};
inline constexpr Text kVariables{
    {"--var", "variables", "defaults of {var:NAME} fields, NAME=VALUE (repeatable; a job file: {\"lot\": \"A00\"})"},
    {}, "none"};

inline constexpr SettingRef kJobSettingList[] = {&kTimeZone, &kShifts, &kVariables};
inline constexpr SettingTable kJobSettings{"job", "The job's variable text", "", kJobSettingList};

// A serial counter ("counters.NAME"; `marker job new` gives every counter of its text these).
inline constexpr WholeRange kCounterValueRange{0, INT64_MAX};
inline constexpr Count kCounterStart{
    {"--start", "start", "first value (and the value after a reset or a wrap)"}, kCounterValueRange, 1};
inline constexpr Count kCounterStep{
    {"--step", "step", "added after each value (negative counts down; not 0)"}, {-INT64_MAX, INT64_MAX}, 1};
inline constexpr Count kCounterLimit{
    {"--limit", "limit", "last value issued"}, kCounterValueRange, {},
    "the largest value `width` digits hold counting up (2⁶³−1 without a width), 0 counting down"};
inline constexpr Choice kAtLimit{
    {"--at-limit", "at_limit",
     "past the limit: stop (the next mark is refused, no number consumed) or wrap (back to start, next cycle)"},
    "stop, wrap", "stop"};
inline constexpr Count kMarksPerSerial{
    {"--marks-per-serial", "marks_per_serial", "parts marked with the same value before it advances"},
    {1, 1'000'000}, 1};
inline constexpr Count kCounterWidth{
    {"--width", "width", "digits (0: as many as needed); the limit must fit"}, {0, 64}, 0};
inline constexpr Choice kPadding{
    {"--padding", "padding",
     "RTC mark_serial: keep leading zeros, suppress them (left-justified), blank them (spaces, right-justified)"},
    "keep, suppress, blank", "keep"};
inline constexpr Choice kAlphabet{
    {"--alphabet", "alphabet", "digits: decimal, hex, base36 (0-9A-Z), base33 (base 36 without I, O, Q)"},
    "decimal, hex, base36, base33", "decimal"};
inline constexpr Text kDigits{
    {"", "digits", "a custom alphabet instead: at least 2 distinct characters, e.g. \"0123456789ACDEFHJKLMNPRTUVWXY\""},
    {}, "none"};
inline constexpr Choice kReset{
    {"--reset", "reset", "restart at start: never, at midnight, at each shift start"}, "never, midnight, shift",
    "never"};
inline constexpr Text kCounterTimeZone{
    {"", "time_zone", "where midnight and shift starts are"}, {}, "the job's"};

inline constexpr SettingRef kCounterSettingList[] = {
    &kCounterStart, &kCounterStep, &kCounterLimit, &kAtLimit, &kMarksPerSerial, &kCounterWidth,
    &kPadding,      &kAlphabet,    &kDigits,       &kReset,   &kCounterTimeZone};
inline constexpr SettingTable kCounterSettings{"counter", "Counter", "counters.NAME", kCounterSettingList};

// The run of `marker mark --job`, the store's administration (`marker serial`) and its log.
inline constexpr Text kSet{
    {"--set", "", "--job: a {var:NAME} value for this run, NAME=VALUE (repeatable)"}, {}, "the job's defaults"};
inline constexpr Count kPartCount{
    {"--count", "", "--job: parts to mark, each with its next serial numbers"}, {1, 1'000'000'000}, 1};
inline constexpr Count kRemark{
    {"--remark", "", "--job: mark the part of audit row ID again (no number consumed)"}, {1, INT64_MAX}};
inline constexpr Text kRemarkReason{
    {"--reason", "", "--job --remark: why the part is marked again (kept in the audit log)"}, {}, "none"};
inline constexpr Toggle kAllowChangedJob{
    {"--allow-changed-job", "",
     "--job --remark: re-mark a part although the job file changed since it was marked (the audit row notes both "
     "versions)"}};
inline constexpr Toggle kCreateCounters{
    {"--create-counters", "", "--job: create the job's counters the store does not know, each at its start"}};
inline constexpr Text kStation{
    {"--station", "", "station name in the audit log; one process per station and store"}, {}, "the host name"};
inline constexpr Count kCreateStart{
    {"--start", "", "serial create: its first value"}, kCounterValueRange, {}, "the job's start, else 1"};
inline constexpr Count kSerialValue{{"value", "", "serial set: the counter's next value"}, kCounterValueRange};
// One reservation issues at most this many values (one audit row each).
inline constexpr Count kReserveCount{{"count", "", "serial reserve: how many values to issue"}, {1, 1'000'000}};
inline constexpr Text kSince{
    {"--since", "",
     "log: rows from this UTC time on: 2026-03-05, 2026-03-05T06:00, or back from now: 90m, 12h, 7d"},
    {}, "every row"};

inline constexpr Count kLogLimit{{"--limit", "", "log: only the last N rows that match"}, {1, 1'000'000'000}, {},
                                 "every row"};
inline constexpr Text kLogSerial{
    {"--serial", "", "log: rows that consumed this value: VALUE or COUNTER=VALUE (and their re-marks)"}, {}, "any"};
inline constexpr Text kLogText{
    {"--text", "", "log: rows that marked exactly this text in an object with a serial field (and their re-marks)"},
    {}, "any"};
inline constexpr Toggle kQuickCheck{
    {"--quick", "", "store check: PRAGMA quick_check only (what every station start runs)"}};
// The store (store_limits.hpp keeps the library's own defaults equal to these).
inline constexpr Count kStoreWait{
    {"--store-wait-ms", "",
     "longest wait for a store another process holds locked (SQLite) or a row lock (PostgreSQL), ms"},
    kStoreWaitMsRange, kStoreWaitMsDefault};
inline constexpr Count kStoreAttempts{
    {"--store-attempts", "",
     "attempts of an allocation or an outcome write before giving up (the outcome stays in the station's journal)"},
    kStoreAttemptsRange, kStoreAttemptsDefault};

inline constexpr SettingRef kRunSettingList[] = {&kSet,         &kPartCount,    &kRemark,   &kRemarkReason, &kAllowChangedJob, &kCreateCounters, &kStation,
                                                 &kCreateStart, &kSerialValue, &kReserveCount, &kSince,    &kLogLimit,
                                                 &kLogSerial,   &kLogText,      &kStoreWait, &kStoreAttempts, &kQuickCheck};
inline constexpr SettingTable kRunSettings{"run", "Production run and serial store", "", kRunSettingList};

}  // namespace mark
