//! [`avx512_twin!`](crate::avx512_twin): a hot loop and its copy compiled for AVX-512F, declared
//! from one parameter list, and [`LoopCopy`] for callers that dispatch themselves.
//!
//! The workspace is built for x86-64-v3 (`.cargo/config.toml`), so every loop is compiled for
//! AVX2 already; only the AVX-512F copy (eight lanes instead of four) needs a second
//! compilation, chosen at run time on CPUs that have it.

/// Declares a function (always inlined, so that it can be compiled into its callers) and, on
/// x86-64, a copy compiled with AVX-512F enabled that only calls it. With
/// `fn dispatch(…) = name / name_avx512 { … }` it also declares `dispatch`, with the attributes
/// and visibility given, which runs the AVX-512F copy on CPUs that have it
/// (`is_x86_feature_detected!("avx512f")`) and the function otherwise. Eight lanes pay for long
/// loops whose iterations are long dependency chains (the traction law), where two 256-bit
/// halves of a 512-bit operation run in parallel. Both give the same bits (no fused
/// multiply–add is ever formed). One optional const generic parameter is passed through. Give
/// every array its own reference argument: only then does the compiler know that they do not
/// overlap and vectorise the loop without run-time checks.
///
/// ```ignore
/// rolldyn_numerics::avx512_twin! {
///     /// Doubles `x` into `y`.
///     fn double(x: &[f64], y: &mut [f64]) = double_portable / double_avx512 {
///         for (y, x) in y.iter_mut().zip(x) { *y = 2.0 * x; }
///     }
/// }
/// ```
#[macro_export]
macro_rules! avx512_twin {
    (
        $(#[$meta:meta])*
        $vis:vis fn $dispatch:ident $(<const $g:ident: $gt:ty>)?
            ($($arg:ident: $ty:ty),* $(,)?) = $name:ident / $avx512:ident
            $body:block
    ) => {
        $(#[$meta])*
        #[allow(clippy::too_many_arguments)]
        $vis fn $dispatch $(<const $g: $gt>)? ($($arg: $ty),*) {
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx512f") {
                // SAFETY: the CPU supports AVX-512F (checked just above).
                unsafe { $avx512 $(::<$g>)? ($($arg),*) };
                return;
            }
            $name $(::<$g>)? ($($arg),*)
        }

        $crate::avx512_twin! {
            #[doc = concat!("The loop of [`", stringify!($dispatch), "`].")]
            fn $name $(<const $g: $gt>)? ($($arg: $ty),*) / $avx512 $body
        }
    };
    (
        $(#[$meta:meta])*
        $vis:vis fn $name:ident $(<const $g:ident: $gt:ty>)?
            ($($arg:ident: $ty:ty),* $(,)?) / $avx512:ident $body:block
    ) => {
        $(#[$meta])*
        #[allow(clippy::too_many_arguments)]
        #[inline(always)]
        $vis fn $name $(<const $g: $gt>)? ($($arg: $ty),*) $body

        #[doc = concat!("[`", stringify!($name), "`] compiled for AVX-512F.\n\n# Safety\n",
            "Only call on a CPU that supports AVX-512F.")]
        #[allow(clippy::too_many_arguments)]
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2,avx512f")]
        $vis unsafe fn $avx512 $(<const $g: $gt>)? ($($arg: $ty),*) {
            $name $(::<$g>)? ($($arg),*)
        }
    };
}

/// Which compiled copy of an [`avx512_twin!`](crate::avx512_twin) loop a caller that
/// dispatches itself runs, ordered by width: a CPU that runs one copy runs every narrower one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum LoopCopy {
    /// the function as built (AVX2 in the x86-64-v3 build)
    Portable,
    /// the AVX-512F copy (eight lanes)
    Avx512,
}

impl LoopCopy {
    /// The widest copy this CPU can run.
    #[inline]
    pub fn detect() -> Self {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx512f") {
            return LoopCopy::Avx512;
        }
        LoopCopy::Portable
    }

    /// Lanes of f64 per vector of this copy (4 for the function as built: one AVX2 vector, or
    /// two SSE2 pairs unrolled), a divisor of [`LoopCopy::MAX_LANES`].
    #[inline]
    pub fn lanes(self) -> usize {
        match self {
            LoopCopy::Portable => 4,
            LoopCopy::Avx512 => 8,
        }
    }

    /// The widest vector, f64 lanes: pad arrays to a multiple of it.
    pub const MAX_LANES: usize = 8;
}
