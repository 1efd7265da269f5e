//! la-tracer (placeholder: being written).
#![deny(missing_docs)]
