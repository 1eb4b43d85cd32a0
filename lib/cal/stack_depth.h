// How far the stack has grown since a point: the bound that keeps deep recursion on hostile input (a
// recursive .cal function, a long chain of definitions) an error rather than a crash.
#pragma once
#include <cstddef>
#include <cstdint>

namespace brume::cal {

class StackDepth {
public:
    StackDepth() : base_(address()) {}
    size_t bytes() const {
        uintptr_t here = address();
        return here > base_ ? here - base_ : base_ - here;
    }

private:
    [[gnu::noinline]] static uintptr_t address() { return reinterpret_cast<uintptr_t>(__builtin_frame_address(0)); }
    uintptr_t base_;
};

// The stack compiling, and each evaluation, may use: about 3000 levels of recursion in a .cal function
// (threads have 8 MB by default, rtrace's 64 MB).
constexpr size_t kMaxStackBytes = 1 << 20;

}  // namespace brume::cal
