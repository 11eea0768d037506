//! [`avx2_twin!`](crate::avx2_twin): a hot loop and its copy compiled for AVX2, declared from one
//! parameter list.

/// Declares a function (always inlined, so that it can be compiled into its callers) and, on
/// x86-64, a copy compiled with AVX2 enabled that only calls it; the caller dispatches at run
/// time (`is_x86_feature_detected!("avx2")`). With `fn dispatch(…) = name / name_avx2 { … }`
/// it also declares `dispatch`, with the attributes and visibility given, which does that
/// dispatch. One optional const generic parameter is passed through. Give every array its own reference argument: only then does the compiler know that
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
            ($($arg:ident: $ty:ty),* $(,)?) = $name:ident / $avx2:ident $body:block
    ) => {
        $(#[$meta])*
        #[allow(clippy::too_many_arguments)]
        $vis fn $dispatch $(<const $g: $gt>)? ($($arg: $ty),*) {
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
            fn $name $(<const $g: $gt>)? ($($arg: $ty),*) / $avx2 $body
        }
    };
    (
        $(#[$meta:meta])*
        $vis:vis fn $name:ident $(<const $g:ident: $gt:ty>)?
            ($($arg:ident: $ty:ty),* $(,)?) / $avx2:ident $body:block
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
    };
}
