"""Where a world's state becomes what a controller reads: the named accessors of the 6-DOF physics
and the observation every world hands to a controller."""
