// A render's state on disk, so that a long render survives a stop: the film's sums and sample counts,
// every pixel, at the end of a pass (`glint render --checkpoint FILE`, `--resume FILE`).
//
// Resuming gives the same bits as a render that never stopped: every pixel's sum is kept exactly (its
// doubles, not an image), the passes continue their fixed schedule from the samples done, and a pixel's
// samples are added in sample order whichever run adds them.
//
// The file (all numbers little-endian, as x86-64 and AArch64 Linux hold them):
//   "GLINTCKP"                      8 bytes
//   format version                  u32 (1)
//   scene fingerprint               u64 (what the render was of: the scene as built, after flags and --set)
//   width, height                   u32, u32 (≤ kMaxImageSide, width × height ≤ kMaxImagePixels)
//   samples done, samples asked     u32, u32 (done < asked: a finished render needs no checkpoint)
//   per pixel, row by row           3 × f64 (sum of r, g, b), f64 (sum of squared luminances),
//                                   u64 (samples in the sums, ≤ samples done)
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/image/film.hpp"

namespace glint {

struct Checkpoint {
    std::uint64_t scene_fingerprint = 0;
    std::uint32_t samples_done = 0;   // every pixel has had samples 0 … samples_done − 1 taken
    std::uint32_t samples_asked = 0;  // the render's samples per pixel once complete
    Film film{0, 0};
};

// A checkpoint file that cannot be resumed: its message names the file and says what is wrong.
struct CheckpointError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::vector<unsigned char> encode_checkpoint(const Checkpoint& checkpoint);
// The same without copying the film into a Checkpoint (what a render in progress writes).
std::vector<unsigned char> encode_checkpoint(std::uint64_t scene_fingerprint, std::uint32_t samples_done,
                                             std::uint32_t samples_asked, const Film& film);

// The length of a checkpoint file of a width × height render: what a reader checks before reading.
std::uint64_t checkpoint_file_bytes(int width, int height);

// Reads a checkpoint from its bytes; `name` is the file name used in messages. Every size is checked
// against the limits and the length of `bytes` before anything is allocated from it; sums must be
// finite and counts at most the samples done. Throws CheckpointError.
Checkpoint decode_checkpoint(const std::vector<unsigned char>& bytes, const std::string& name);

// Checks that `checkpoint` belongs to the render about to start: the same scene fingerprint, image size
// and samples asked. Throws CheckpointError naming `name` and what differs.
void check_checkpoint_matches(const Checkpoint& checkpoint, const std::string& name,
                              std::uint64_t fingerprint, int width, int height, std::uint32_t samples_asked);

}  // namespace glint
