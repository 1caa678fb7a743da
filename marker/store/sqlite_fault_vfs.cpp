#include "marker/store/sqlite_fault_vfs.hpp"

#include <sqlite3.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace mark {
namespace {

std::mutex g_mutex;
std::string g_path;               // guarded by g_mutex
std::atomic<int> g_code{0};       // 0: no fault

struct FaultFile {
  sqlite3_file base;
  sqlite3_file* real;
  const char* name;  // valid until xClose (SQLite's promise for xOpen's name)
};

sqlite3_vfs* real_vfs() { return sqlite3_vfs_find(nullptr); }
sqlite3_file* real(sqlite3_file* f) { return reinterpret_cast<FaultFile*>(f)->real; }

// The fault applies to the database file and every file whose name starts with its path.
int fault_for(sqlite3_file* f) {
  const int code = g_code.load(std::memory_order_acquire);
  if (code == 0) return 0;
  const char* name = reinterpret_cast<FaultFile*>(f)->name;
  std::lock_guard lock(g_mutex);
  return name && std::strncmp(name, g_path.c_str(), g_path.size()) == 0 ? code : 0;
}

int x_close(sqlite3_file* f) {
  const int rc = real(f)->pMethods->xClose(real(f));
  f->pMethods = nullptr;
  return rc;
}
int x_read(sqlite3_file* f, void* p, int n, sqlite3_int64 off) { return real(f)->pMethods->xRead(real(f), p, n, off); }
int x_write(sqlite3_file* f, const void* p, int n, sqlite3_int64 off) {
  if (const int code = fault_for(f)) return code;
  return real(f)->pMethods->xWrite(real(f), p, n, off);
}
int x_truncate(sqlite3_file* f, sqlite3_int64 size) {
  if (const int code = fault_for(f)) return code == SQLITE_FULL ? SQLITE_FULL : SQLITE_IOERR_TRUNCATE;
  return real(f)->pMethods->xTruncate(real(f), size);
}
int x_sync(sqlite3_file* f, int flags) {
  if (fault_for(f) == SQLITE_IOERR_WRITE) return SQLITE_IOERR_FSYNC;
  return real(f)->pMethods->xSync(real(f), flags);
}
int x_file_size(sqlite3_file* f, sqlite3_int64* size) { return real(f)->pMethods->xFileSize(real(f), size); }
int x_lock(sqlite3_file* f, int l) { return real(f)->pMethods->xLock(real(f), l); }
int x_unlock(sqlite3_file* f, int l) { return real(f)->pMethods->xUnlock(real(f), l); }
int x_check_reserved(sqlite3_file* f, int* out) { return real(f)->pMethods->xCheckReservedLock(real(f), out); }
int x_file_control(sqlite3_file* f, int op, void* arg) { return real(f)->pMethods->xFileControl(real(f), op, arg); }
int x_sector_size(sqlite3_file* f) { return real(f)->pMethods->xSectorSize(real(f)); }
int x_device(sqlite3_file* f) { return real(f)->pMethods->xDeviceCharacteristics(real(f)); }
int x_shm_map(sqlite3_file* f, int i, int sz, int extend, void volatile** p) {
  return real(f)->pMethods->xShmMap(real(f), i, sz, extend, p);
}
int x_shm_lock(sqlite3_file* f, int off, int n, int flags) { return real(f)->pMethods->xShmLock(real(f), off, n, flags); }
void x_shm_barrier(sqlite3_file* f) { real(f)->pMethods->xShmBarrier(real(f)); }
int x_shm_unmap(sqlite3_file* f, int del) { return real(f)->pMethods->xShmUnmap(real(f), del); }
int x_fetch(sqlite3_file* f, sqlite3_int64 off, int n, void** p) { return real(f)->pMethods->xFetch(real(f), off, n, p); }
int x_unfetch(sqlite3_file* f, sqlite3_int64 off, void* p) { return real(f)->pMethods->xUnfetch(real(f), off, p); }

const sqlite3_io_methods kMethods = {
    3,          x_close,     x_read,       x_write,          x_truncate,     x_sync,
    x_file_size, x_lock,     x_unlock,     x_check_reserved, x_file_control, x_sector_size,
    x_device,   x_shm_map,   x_shm_lock,   x_shm_barrier,    x_shm_unmap,    x_fetch,
    x_unfetch};

int v_open(sqlite3_vfs*, sqlite3_filename name, sqlite3_file* f, int flags, int* out_flags) {
  auto* ff = reinterpret_cast<FaultFile*>(f);
  ff->real = reinterpret_cast<sqlite3_file*>(ff + 1);
  ff->name = name;
  const int rc = real_vfs()->xOpen(real_vfs(), name, ff->real, flags, out_flags);
  // Our methods only over a real file that opened (SQLite calls xClose only when pMethods is set).
  f->pMethods = ff->real->pMethods ? &kMethods : nullptr;
  return rc;
}
int v_delete(sqlite3_vfs*, const char* name, int sync) { return real_vfs()->xDelete(real_vfs(), name, sync); }
int v_access(sqlite3_vfs*, const char* name, int flags, int* out) { return real_vfs()->xAccess(real_vfs(), name, flags, out); }
int v_full(sqlite3_vfs*, const char* name, int n, char* out) { return real_vfs()->xFullPathname(real_vfs(), name, n, out); }
void* v_dlopen(sqlite3_vfs*, const char* name) { return real_vfs()->xDlOpen(real_vfs(), name); }
void v_dlerror(sqlite3_vfs*, int n, char* out) { real_vfs()->xDlError(real_vfs(), n, out); }
void (*v_dlsym(sqlite3_vfs*, void* h, const char* sym))(void) { return real_vfs()->xDlSym(real_vfs(), h, sym); }
void v_dlclose(sqlite3_vfs*, void* h) { real_vfs()->xDlClose(real_vfs(), h); }
int v_random(sqlite3_vfs*, int n, char* out) { return real_vfs()->xRandomness(real_vfs(), n, out); }
int v_sleep(sqlite3_vfs*, int us) { return real_vfs()->xSleep(real_vfs(), us); }
int v_time(sqlite3_vfs*, double* t) { return real_vfs()->xCurrentTime(real_vfs(), t); }
int v_last_error(sqlite3_vfs*, int n, char* out) { return real_vfs()->xGetLastError(real_vfs(), n, out); }
int v_time64(sqlite3_vfs*, sqlite3_int64* t) { return real_vfs()->xCurrentTimeInt64(real_vfs(), t); }

}  // namespace

const char* sqlite_fault_vfs() {
  static const char* name = [] {
    static sqlite3_vfs vfs{};
    sqlite3_vfs* base = real_vfs();
    vfs.iVersion = 2;
    vfs.szOsFile = static_cast<int>(sizeof(FaultFile)) + base->szOsFile;
    vfs.mxPathname = base->mxPathname;
    vfs.zName = "marker-faults";
    vfs.xOpen = v_open;
    vfs.xDelete = v_delete;
    vfs.xAccess = v_access;
    vfs.xFullPathname = v_full;
    vfs.xDlOpen = v_dlopen;
    vfs.xDlError = v_dlerror;
    vfs.xDlSym = v_dlsym;
    vfs.xDlClose = v_dlclose;
    vfs.xRandomness = v_random;
    vfs.xSleep = v_sleep;
    vfs.xCurrentTime = v_time;
    vfs.xGetLastError = v_last_error;
    vfs.xCurrentTimeInt64 = v_time64;
    sqlite3_vfs_register(&vfs, 0);
    return vfs.zName;
  }();
  return name;
}

void sqlite_fail_writes(const std::string& db_path, int sqlite_code) {
  {
    std::lock_guard lock(g_mutex);
    g_path = db_path;
  }
  g_code.store(sqlite_code, std::memory_order_release);
}

}  // namespace mark
