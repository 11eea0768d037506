//! Physical dimensions: the runtime [`Dimension`](crate::Dimension) enum and the compile-time
//! marker types naming the dimension of a [`Quantity`](crate::Quantity), generated together.

use crate::unit_table::Dimension;

/// A compile-time dimension marker.
pub trait Dim: Copy + Clone + std::fmt::Debug + PartialEq + 'static {
    const DIMENSION: Dimension;
}

/// Declares every dimension once: the `Dimension` enum with its human name and SI symbol, and
/// one marker type per dimension.
macro_rules! dimensions {
    ($($name:ident => $human:literal, $si:literal;)*) => {
        /// A physical dimension a quantity can have.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Dimension {
            $($name,)*
        }

        impl Dimension {
            /// Human name used in error messages.
            pub fn name(self) -> &'static str {
                match self {
                    $(Self::$name => $human,)*
                }
            }

            /// SI unit symbol, used when a plain number is given and in messages.
            pub fn si_symbol(self) -> &'static str {
                match self {
                    $(Self::$name => $si,)*
                }
            }
        }

        /// Compile-time markers, one per [`Dimension`].
        pub mod markers {
            $(
                #[doc = concat!("Marker for ", $human, " (", $si, ").")]
                #[derive(Debug, Clone, Copy, PartialEq)]
                pub struct $name;
                impl super::Dim for $name {
                    const DIMENSION: super::Dimension = super::Dimension::$name;
                }
            )*
        }
    };
}
pub(crate) use dimensions;
