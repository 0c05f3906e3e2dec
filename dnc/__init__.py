"""The serial layer: framing, flow control, send, receive, emulator, gateway (not yet built)."""
