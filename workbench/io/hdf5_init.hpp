#pragma once
// One-time set-up of the HDF5 library for this process, called before the first HDF5 call of any
// io/ function: errors are reported by us (not printed by HDF5), and the library does not run its
// own clean-up at exit. That clean-up closes files left open, and a file whose close failed (a
// full disk) makes it crash the process after we have already reported the failure; every file
// we open is closed explicitly, so nothing is lost by skipping it.
namespace rb::io {
void initHdf5();
}  // namespace rb::io
