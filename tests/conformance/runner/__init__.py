"""The conformance runner's library: case loading, TOML emission, ncc invocation, comparison."""
