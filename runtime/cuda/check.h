/* check.h — a CUDA call checked: on failure the program stops with its message and the
 * exit code of a CUDA failure. */
#ifndef SPHRT_CUDA_CHECK_H
#define SPHRT_CUDA_CHECK_H

#include <cstdlib>

#include "target.h"
#include "core/exit_codes.h"
#include "core/message.h"

#define SPH_CUDA_CHECK(call)                                                                   \
    do {                                                                                       \
        cudaError_t err_ = (call);                                                             \
        if (err_ != cudaSuccess) {                                                             \
            sph_error("CUDA: %s failed: %s", #call, cudaGetErrorString(err_));                 \
            exit(SPH_EXIT_CUDA);                                                               \
        }                                                                                      \
    } while (0)

#endif
