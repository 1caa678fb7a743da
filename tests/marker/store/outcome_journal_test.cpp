// The outcome journal: what was appended survives a reopen, applied entries do not come back, a
// line torn by a crash is cut off (and the next append is whole), a damaged line is skipped,
// one process at a time, space reserved ahead, emptied once nothing is pending.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "marker/store/outcome_journal.hpp"
#include "marker/store/store_error.hpp"
#include "store_test_support.hpp"

namespace mark {
namespace {

JournalEntry entry(std::int64_t id, Outcome o = Outcome::done) {
  JournalEntry e;
  e.mark_id = id;
  e.outcome.time_utc = "2026-03-05T09:41:00.000000Z";
  e.outcome.outcome = o;
  e.outcome.figures = {{"mark_time_s", 0.07}, {"device", "sim SL10"}};
  e.serials = {{"sn", id}};
  e.text = "SN " + std::to_string(id);
  return e;
}

std::vector<std::int64_t> ids(const OutcomeJournal& j) {
  std::vector<std::int64_t> out;
  for (const JournalEntry& e : j.pending()) out.push_back(e.mark_id);
  return out;
}

struct Journal : testing::Test {
  std::filesystem::path dir = test::fresh_store_dir("journal");
  void TearDown() override { std::filesystem::remove_all(dir); }
};

TEST_F(Journal, WhatWasAppendedSurvivesAndAppliedEntriesDoNotComeBack) {
  {
    OutcomeJournal j(dir.string(), "store-1", "line 1");
    j.append(entry(7));
    j.append(entry(8, Outcome::aborted));
    j.append(entry(9));
    j.applied(8);
  }
  OutcomeJournal j(dir.string(), "store-1", "line 1");
  EXPECT_EQ(ids(j), (std::vector<std::int64_t>{7, 9}));
  const JournalEntry e = j.pending().front();
  EXPECT_EQ(e.outcome.outcome, Outcome::done);
  EXPECT_EQ(e.outcome.figures.at("device"), "sim SL10");
  EXPECT_EQ(e.serials.at("sn"), 7);
  EXPECT_EQ(e.text, "SN 7");
  EXPECT_EQ(j.path(), (dir / "outcomes-store-1-line%201.jsonl").string());
  // Another store or station: another journal.
  EXPECT_TRUE(OutcomeJournal(dir.string(), "store-2", "line 1").empty());
}

TEST_F(Journal, ATornLineIsCutAndADamagedOneSkipped) {
  std::string path;
  {
    OutcomeJournal j(dir.string(), "s", "st");
    j.append(entry(1));
    j.append(entry(2));
    path = j.path();
  }
  {
    // A crash mid-write leaves half a line; a bit flipped on the disk breaks a checksum.
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(f)), {});
    const std::size_t second = text.find('\n') + 1;
    text[second + 30] ^= 1;
    text += "0123456789abcdef {\"kind\":\"outcome\",\"mark_id\":3";
    f.seekp(0);
    f << text;
  }
  OutcomeJournal j(dir.string(), "s", "st");
  EXPECT_EQ(ids(j), (std::vector<std::int64_t>{1}));
  j.append(entry(4));
  EXPECT_EQ(ids(j), (std::vector<std::int64_t>{1, 4}));
}

TEST_F(Journal, AfterATornLineTheNextAppendIsWhole) {
  std::string path;
  {
    OutcomeJournal j(dir.string(), "s", "st");
    j.append(entry(1));
    path = j.path();
  }
  std::ofstream(path, std::ios::app) << "abc {\"kind\":";
  { OutcomeJournal(dir.string(), "s", "st").append(entry(2)); }
  EXPECT_EQ(ids(OutcomeJournal(dir.string(), "s", "st")), (std::vector<std::int64_t>{1, 2}));
}

TEST_F(Journal, OneProcessAtATime) {
  OutcomeJournal first(dir.string(), "s", "st");
  try {
    OutcomeJournal second(dir.string(), "s", "st");
    FAIL() << "two writers of one journal";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("is in use by another process"), std::string::npos);
    EXPECT_EQ(e.kind(), StoreErrorKind::busy);
  }
}

TEST_F(Journal, SpaceIsReservedAndTheFileEmptiedWhenNothingIsPending) {
  OutcomeJournal j(dir.string(), "s", "st");
  struct stat st {};
  ASSERT_EQ(stat(j.path().c_str(), &st), 0);
  // At least a MiB allocated past the (empty) end: appends need no new blocks on a full disk.
  EXPECT_GE(static_cast<long long>(st.st_blocks) * 512, 1 << 20);
  EXPECT_EQ(st.st_size, 0);
  for (int i = 1; i <= 3000; ++i) {
    j.append(entry(i));
    j.applied(i);
  }
  ASSERT_EQ(stat(j.path().c_str(), &st), 0);
  EXPECT_LT(st.st_size, 256 << 10) << "the journal grows without bound";
  EXPECT_TRUE(j.empty());
}

}  // namespace
}  // namespace mark
