"""What the lowering (`rdisc.lower`) builds from parts of the Model: the engine's data objects,
each with the constructor call that made it (`constructs`), and the ROS 2 messages a recording
carries (`messages`). Below the plans: the runtime and the emitters read them through the plans."""
