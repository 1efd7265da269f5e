//! Shared glue for the command-line programs (placeholder).
pub mod scenes;
