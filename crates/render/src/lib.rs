//! render (placeholder: being written).
#![deny(missing_docs)]
