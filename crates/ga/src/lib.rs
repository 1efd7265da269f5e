//! Geometric algebra (placeholder: being written).
#![deny(missing_docs)]
