"""The runtime: simulate a compiled world and run its controllers in lockstep."""
