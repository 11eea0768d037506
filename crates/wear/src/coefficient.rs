//! placeholder owned by helper
