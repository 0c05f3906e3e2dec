"""The serial layer: framing, flow control, send, receive, the control emulator, the multi-port
gateway and its Modbus interface."""
