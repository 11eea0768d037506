//! [`avx2_twin!`](crate::avx2_twin): a hot loop and its copies compiled for AVX2 (and, optionally,
//! AVX-512F), declared from one parameter list.

/// Declares a function (always inlined, so that it can be compiled into its callers) and, on
/// x86-64, a copy compiled with AVX2 enabled that only calls it; the caller dispatches at run
/// time (`is_x86_feature_detected!("avx2")`). With `fn dispatch(…) = name / name_avx2 { … }`
/// it also declares `dispatch`, with the attributes and visibility given, which does that
/// dispatch. With a third name (`= name / name_avx2 / name_avx512`) a copy compiled with AVX-512F
/// is declared too and preferred by the dispatch on CPUs that have it: eight lanes instead of
/// four, which pays for long loops whose iterations are long dependency chains (the traction
/// law), where two 256-bit halves of a 512-bit operation run in parallel. All copies give the
/// same bits (no fused multiply–add is ever formed). One optional const generic parameter is
/// passed through. Give every array its own reference argument: only then does the compiler know that
/// they do not overlap and vectorise the loop without run-time checks.
///
/// ```ignore
/// rolldyn_numerics::avx2_twin! {
///     /// Doubles `x` into `y`.
///     fn double(x: &[f64], y: &mut [f64]) / double_avx2 {
///         for (y, x) in y.iter_mut().zip(x) { *y = 2.0 * x; }
///     }
/// }
/// ```
#[macro_export]
macro_rules! avx2_twin {
    (
        $(#[$meta:meta])*
        $vis:vis fn $dispatch:ident $(<const $g:ident: $gt:ty>)?
            ($($arg:ident: $ty:ty),* $(,)?) = $name:ident / $avx2:ident $(/ $avx512:ident)?
            $body:block
    ) => {
        $(#[$meta])*
        #[allow(clippy::too_many_arguments)]
        $vis fn $dispatch $(<const $g: $gt>)? ($($arg: $ty),*) {
            $crate::avx2_twin!(@call_avx512 [$($avx512)?] [$($g)?] ($($arg),*));
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU supports AVX2 (checked just above).
                unsafe { $avx2 $(::<$g>)? ($($arg),*) };
                return;
            }
            $name $(::<$g>)? ($($arg),*)
        }

        $crate::avx2_twin! {
            #[doc = concat!("The loop of [`", stringify!($dispatch), "`].")]
            fn $name $(<const $g: $gt>)? ($($arg: $ty),*) / $avx2 $(/ $avx512)? $body
        }
    };
    (
        $(#[$meta:meta])*
        $vis:vis fn $name:ident $(<const $g:ident: $gt:ty>)?
            ($($arg:ident: $ty:ty),* $(,)?) / $avx2:ident $(/ $avx512:ident)? $body:block
    ) => {
        $(#[$meta])*
        #[allow(clippy::too_many_arguments)]
        #[inline(always)]
        $vis fn $name $(<const $g: $gt>)? ($($arg: $ty),*) $body

        #[doc = concat!("[`", stringify!($name), "`] compiled for AVX2.\n\n# Safety\n",
            "Only call on a CPU that supports AVX2.")]
        #[allow(clippy::too_many_arguments)]
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2")]
        $vis unsafe fn $avx2 $(<const $g: $gt>)? ($($arg: $ty),*) {
            $name $(::<$g>)? ($($arg),*)
        }

        $crate::avx2_twin!(@define_avx512 [$($avx512)?] $vis $name [$(<const $g: $gt>)?] [$($g)?]
            ($($arg: $ty),*));
    };
    (@call_avx512 [] [$($g:ident)?] ($($arg:ident),*)) => {};
    (@call_avx512 [$avx512:ident] [$($g:ident)?] ($($arg:ident),*)) => {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx512f") {
            // SAFETY: the CPU supports AVX-512F (checked just above).
            unsafe { $avx512 $(::<$g>)? ($($arg),*) };
            return;
        }
    };
    (@define_avx512 [] $vis:vis $name:ident [$($generics:tt)*] [$($g:ident)?]
        ($($arg:ident: $ty:ty),*)) => {};
    (@define_avx512 [$avx512:ident] $vis:vis $name:ident [$($generics:tt)*] [$($g:ident)?]
        ($($arg:ident: $ty:ty),*)) => {
        #[doc = concat!("[`", stringify!($name), "`] compiled for AVX-512F.\n\n# Safety\n",
            "Only call on a CPU that supports AVX-512F.")]
        #[allow(clippy::too_many_arguments)]
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2,avx512f")]
        $vis unsafe fn $avx512 $($generics)* ($($arg: $ty),*) {
            $name $(::<$g>)? ($($arg),*)
        }
    };
}

/// Which compiled copy of an [`avx2_twin!`](crate::avx2_twin) loop a caller that dispatches
/// itself runs, ordered by width: a CPU that runs one copy runs every narrower one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum LoopCopy {
    /// the portable loop (baseline instruction set)
    Portable,
    /// the AVX2 copy (four lanes)
    Avx2,
    /// the AVX-512F copy (eight lanes)
    Avx512,
}

impl LoopCopy {
    /// The widest copy this CPU can run.
    #[inline]
    pub fn detect() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx512f") {
                return LoopCopy::Avx512;
            }
            if std::arch::is_x86_feature_detected!("avx2") {
                return LoopCopy::Avx2;
            }
        }
        LoopCopy::Portable
    }

    /// Lanes of f64 per vector of this copy (4 for the portable loop: its SSE2 pairs are
    /// unrolled by two), a divisor of [`LoopCopy::MAX_LANES`].
    #[inline]
    pub fn lanes(self) -> usize {
        match self {
            LoopCopy::Portable | LoopCopy::Avx2 => 4,
            LoopCopy::Avx512 => 8,
        }
    }

    /// The widest vector, f64 lanes: pad arrays to a multiple of it.
    pub const MAX_LANES: usize = 8;
}
