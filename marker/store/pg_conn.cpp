#include "marker/store/pg_conn.hpp"

#include <poll.h>

#include <cstring>
#include <exception>
#include <vector>

namespace mark {
namespace {

StoreErrorKind kind_of(const char* sqlstate, bool cancel_sent) {
  const std::string s = sqlstate ? sqlstate : "";
  if (s == "55P03" || s == "40001" || s == "40P01") return StoreErrorKind::busy;  // lock timeout, retry
  if (s == "57014") return cancel_sent ? StoreErrorKind::cancelled : StoreErrorKind::busy;  // statement timeout
  if (s.rfind("08", 0) == 0 || s == "57P01" || s == "57P02" || s == "57P03") return StoreErrorKind::connection;
  if (s.rfind("23", 0) == 0) return StoreErrorKind::constraint;
  if (s.rfind("53", 0) == 0) return StoreErrorKind::full;
  if (s == "XX001" || s == "XX002") return StoreErrorKind::corrupt;
  return StoreErrorKind::other;
}

}  // namespace

std::string pg_first_line(const std::string& s) {
  const std::size_t nl = s.find('\n');
  return nl == std::string::npos ? s : s.substr(0, nl);
}

std::string pg_redacted(const std::string& url) {
  const std::size_t scheme = url.find("://");
  const std::size_t at = url.find('@');
  if (scheme == std::string::npos || at == std::string::npos) return url;
  const std::size_t colon = url.find(':', scheme + 3);
  if (colon == std::string::npos || colon > at) return url;
  return url.substr(0, colon) + ":***" + url.substr(at);
}

PgResult& PgResult::operator=(PgResult&& o) noexcept {
  if (this != &o) {
    PQclear(r_);
    r_ = o.r_;
    o.r_ = nullptr;
  }
  return *this;
}

PgConn::PgConn(const std::string& url, const PgOptions& options) : url_(url), options_(options) {
  const std::string timeout = std::to_string(options.connect_timeout_s);
  // The URL comes last, so a connect_timeout it names itself wins.
  const char* keys[] = {"connect_timeout", "dbname", nullptr};
  const char* values[] = {timeout.c_str(), url.c_str(), nullptr};
  c_ = PQconnectdbParams(keys, values, 1);
  if (PQstatus(c_) != CONNECTION_OK) {
    const std::string msg = PQerrorMessage(c_);
    PQfinish(c_);
    c_ = nullptr;
    throw StoreError("serial store " + pg_redacted(url) + ": cannot connect: " + pg_first_line(msg),
                     StoreErrorKind::connection);
  }
  const std::string host = PQhost(c_) ? PQhost(c_) : "";
  describe_ = "postgresql://" + std::string(PQuser(c_)) + "@" + host + ":" + PQport(c_) + "/" + PQdb(c_);
  setup_session();
}

PgConn::~PgConn() {
  if (c_) PQfinish(c_);
}

void PgConn::setup_session() {
  run("SET client_min_messages = warning; SET lock_timeout = '" + std::to_string(options_.lock_timeout_ms) +
      "ms'; SET statement_timeout = '" + std::to_string(options_.statement_timeout_ms) +
      "ms'; SET idle_in_transaction_session_timeout = '60s'");
}

void PgConn::reset() {
  PQreset(c_);
  if (PQstatus(c_) != CONNECTION_OK)
    throw StoreError("serial store " + describe_ + ": cannot connect again: " + pg_first_line(PQerrorMessage(c_)),
                     StoreErrorKind::connection);
  setup_session();
}

void PgConn::send(const std::string& sql, const std::vector<std::optional<std::string>>& params,
                  bool single_row) {
  cancel_sent_ = false;
  std::vector<const char*> values;
  for (const auto& p : params) values.push_back(p ? p->c_str() : nullptr);
  const int ok = params.empty() && !single_row
                     ? PQsendQuery(c_, sql.c_str())
                     : PQsendQueryParams(c_, sql.c_str(), static_cast<int>(values.size()), nullptr,
                                         values.data(), nullptr, nullptr, 0);
  if (!ok) fail(nullptr);
  if (single_row) PQsetSingleRowMode(c_);
}

PGresult* PgConn::next_result() {
  for (;;) {
    if (!PQconsumeInput(c_)) fail(nullptr);
    if (!PQisBusy(c_)) return PQgetResult(c_);
    if (cancel_ && !cancel_sent_ && cancel_()) {
      // Ask the server to stop the statement (a lock wait, a long query); its error follows.
      if (PGcancel* pc = PQgetCancel(c_)) {
        char err[256];
        PQcancel(pc, err, sizeof err);
        PQfreeCancel(pc);
      }
      cancel_sent_ = true;
    }
    pollfd p{PQsocket(c_), POLLIN, 0};
    ::poll(&p, 1, 20);
  }
}

void PgConn::fail(PGresult* r) {
  const bool bad = PQstatus(c_) != CONNECTION_OK;
  const char* state = r ? PQresultErrorField(r, PG_DIAG_SQLSTATE) : nullptr;
  std::string msg = r ? PQresultErrorMessage(r) : PQerrorMessage(c_);
  const StoreErrorKind kind = bad || !r ? StoreErrorKind::connection : kind_of(state, cancel_sent_);
  PQclear(r);
  if (msg.empty()) msg = "the server closed the connection";
  if (kind == StoreErrorKind::cancelled) msg = "cancelled while waiting for the server";
  throw StoreError("serial store " + describe_ + ": " + pg_first_line(msg), kind);
}

PgResult PgConn::run(const std::string& sql, PgParams params) {
  return run(sql, std::vector<std::optional<std::string>>(params));
}

PgResult PgConn::run(const std::string& sql, const std::vector<std::optional<std::string>>& params) {
  send(sql, params, false);
  PgResult last;
  // Owned here until fail() takes it: the next read can throw (the connection lost after the
  // error came in), and a raw pointer held across it leaked (found by the ASan run of the tests).
  PgResult error;
  while (PGresult* r = next_result()) {
    const ExecStatusType st = PQresultStatus(r);
    if (st != PGRES_COMMAND_OK && st != PGRES_TUPLES_OK) {
      if (!error) error = PgResult(r);
      else PQclear(r);
      continue;  // every result is read before the connection takes another command
    }
    last = PgResult(r);
  }
  if (error || PQstatus(c_) != CONNECTION_OK) fail(error.release());
  return last;
}

void PgConn::stream(const std::string& sql, const std::vector<std::optional<std::string>>& params,
                    const std::function<bool(const PgResult&)>& row) {
  send(sql, params, true);
  bool wanted = true;
  std::exception_ptr failure;
  PgResult error;  // owned across the reads that can throw (run() above)
  const auto stop = [&] {
    // The rest is not wanted: ask the server to stop sending it (its "canceled" error is ours).
    wanted = false;
    if (PGcancel* pc = PQgetCancel(c_)) {
      char err[256];
      PQcancel(pc, err, sizeof err);
      PQfreeCancel(pc);
    }
  };
  while (PGresult* r = next_result()) {
    const ExecStatusType st = PQresultStatus(r);
    if (st == PGRES_SINGLE_TUPLE && wanted) {
      const PgResult one(r);
      try {
        if (!row(one)) stop();
      } catch (...) {
        failure = std::current_exception();
        stop();
      }
    } else if (st == PGRES_SINGLE_TUPLE || st == PGRES_TUPLES_OK || !wanted) {
      PQclear(r);
    } else if (!error) {
      error = PgResult(r);
    } else {
      PQclear(r);
    }
  }
  if (error || PQstatus(c_) != CONNECTION_OK) fail(error.release());
  if (failure) std::rethrow_exception(failure);
}

}  // namespace mark
