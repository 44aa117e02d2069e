"""The model's learning (the paper's section 2.2): the Kohonen maps, the Jordan network that
learns the grasps from them, its training, and the network variants a run can ask for."""
