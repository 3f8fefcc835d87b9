// The number of threads the compiled core's parallel kernels use (the apparent-pair search of the
// implicit Rips engine, the witness complex), as the Python layer and the tests can ask for it.
#include "arrays.hpp"

NB_MODULE(threads, m) {
    m.doc() = "The thread count of the compiled core's parallel kernels.";
    m.def("thread_count", &thesis::thread_count, nanobind::arg("n_threads") = 0,
          "n_threads when positive, else OMP_NUM_THREADS when set to a positive integer, else the "
          "number of hardware threads (at least 1).");
}
