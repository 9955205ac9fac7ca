// Harness checkpoint: a render checkpoint file (`glint render --resume FILE`) through decode_checkpoint,
// as the CLI reads it before resuming.
//
// Findings: a crash, a leak, an allocation the header's checks should have refused, an exception other
// than CheckpointError, or a checkpoint that decodes but does not encode back to the same bytes (the
// format has one encoding for each state, so a reader that accepts more has skipped a check).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz_support.hpp"
#include "glint/render/checkpoint.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<unsigned char> bytes(data, data + size);
    glint::Checkpoint checkpoint;
    try {
        checkpoint = glint::decode_checkpoint(bytes, "fuzz.ckpt");
    } catch (const glint::CheckpointError&) {
        return 0;
    }
    GLINT_FUZZ_CHECK(checkpoint.samples_done > 0 && checkpoint.samples_done < checkpoint.samples_asked);
    GLINT_FUZZ_CHECK(glint::encode_checkpoint(checkpoint) == bytes);
    return 0;
}
