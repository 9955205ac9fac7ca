// `mpirun -np N glint render …`: one image spread over the ranks of an MPI job (mpi_render.cpp, built
// when CMake finds MPI; docs/distributed.md).
#pragma once

#include <cstdlib>
#include <string>

#include "render_setup.hpp"

namespace glint::cli {

// Whether this process was started by an MPI launcher, read from the environment it sets: OpenMPI's
// mpirun (OMPI_COMM_WORLD_SIZE), a PMI-2 launcher such as Slurm's `srun --mpi=pmi2` or MPICH's hydra
// (PMI_SIZE), a PMIx one such as `srun --mpi=pmix` (PMIX_RANK). glint calls MPI_Init only then: a
// plain `glint render` stays exactly what it was (OpenMPI's MPI_Init outside mpirun starts a
// "singleton" runtime, which costs time and may warn about the network), and MPI's leaks and threads
// never reach the other commands or the tests.
inline bool launched_by_mpi() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
        if (std::getenv(variable) != nullptr) {
            return true;
        }
    }
    return false;
}

// The ranks of the job, as the launcher says (0 when it does not): what a glint built without MPI
// checks, to refuse rather than have every rank render the whole image into the same file.
inline int launched_ranks() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_NTASKS"}) {
        if (const char* value = std::getenv(variable)) {
            return std::atoi(value);
        }
    }
    return 0;
}

#ifdef GLINT_HAVE_MPI
// Renders `options` over the ranks of the MPI job: rank 0 hands out bands of rows one at a time to
// whichever rank asks (itself included, on a thread of its own), gathers their pixels and writes the
// image, bit for bit that of one `glint render`. Returns the process's exit code; a rank that fails
// mid-render ends the whole job through MPI_Abort.
int run_mpi_render(const RenderOptions& options);
#endif

}  // namespace glint::cli
