"""The body and its vision (the paper's section 2.1): the simulated iCub arm and hand, their
inverse kinematics, the grasps and the demonstrations of them, and the eye's visual maps."""
