//! Helpers shared by the benches: results/ paths and CSV writing (placeholder).
