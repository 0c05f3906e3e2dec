"""The post-processor checker: modal state, rules, geometry, reports (not yet built)."""
