//! Runtime selection of wider vector instructions for hot element-wise loops.
//!
//! [`wide_loop!`] compiles a loop body three times — for the baseline target, with AVX2 and with
//! AVX-512F — and picks the widest copy the CPU supports at run time (a portable binary that still
//! uses the machine's full vector width). All copies perform the same IEEE operations in the same
//! order (no fused multiply-add: Rust never contracts `a * b + c` on its own), so results are
//! bit-identical whichever copy runs.
//!
//! This is the one place the kernel uses `unsafe`: calling a `#[target_feature]` function, which
//! is sound exactly when the feature was detected on the running CPU, as checked right before.

/// True when the running CPU supports AVX2 (cached by the standard library).
#[inline]
pub fn avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// True when the running CPU supports AVX-512F.
#[inline]
pub fn avx512() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx512f")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Defines a function whose body is compiled for the baseline target, AVX2 and AVX-512F,
/// dispatched at run time. The body must be an element-wise loop (it is force-inlined into both copies).
#[macro_export]
macro_rules! wide_loop {
    ($(#[$m:meta])* $vis:vis fn $name:ident($($arg:ident : $ty:ty),* $(,)?) $body:block) => {
        $(#[$m])*
        #[allow(unsafe_code)]
        $vis fn $name($($arg: $ty),*) {
            #[inline(always)]
            fn body($($arg: $ty),*) $body
            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "avx512f")]
                fn widest($($arg: $ty),*) {
                    body($($arg),*)
                }
                #[target_feature(enable = "avx2")]
                fn wide($($arg: $ty),*) {
                    body($($arg),*)
                }
                if $crate::simd::avx512() {
                    // SAFETY: `widest` only requires AVX-512F, detected on this CPU.
                    return unsafe { widest($($arg),*) };
                }
                if $crate::simd::avx2() {
                    // SAFETY: `wide` only requires AVX2, which the running CPU was just shown
                    // to support.
                    return unsafe { wide($($arg),*) };
                }
            }
            body($($arg),*)
        }
    };
}

pub use crate::wide_loop;
