//! Topology report (placeholder until the module lands).

/// Topology report (placeholder).
#[derive(Debug, Clone, Default)]
pub struct TopologyReport;
