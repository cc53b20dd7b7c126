"""Where an output's declared noise goes in a ROS message (thesis §7.2.3): a field's variance on
the diagonal of the covariance its message keeps beside it, found by the field's path in the
framework's message (the adapter's `ros` paths as stdlib/frameworks.txt's column makes them),
one table for both ROS versions. A message without such a field (`Range`, `JointState`) carries no covariance; fields
the description gives no noise leave 0."""

from __future__ import annotations

from rdisc.semantics import model as m

# A field's path → the covariance beside it, that square matrix's side, the field's place on its diagonal.
# nav_msgs/Odometry and geometry_msgs/*WithCovariance: x, y, z, rotation about x, y, z (REP 103);
# sensor_msgs/Imu: its three vectors' x, y, z, the orientation's roll, pitch, yaw.
_AXES = {"x": 0, "y": 1, "z": 2}
DIAGONALS: dict[str, tuple[str, int, int]] = {
    **{f"pose.pose.position.{axis}": ("pose.covariance", 6, at) for axis, at in _AXES.items()},
    "pose.pose.orientation:yaw": ("pose.covariance", 6, 5),
    **{f"twist.twist.linear.{axis}": ("twist.covariance", 6, at) for axis, at in _AXES.items()},
    **{f"twist.twist.angular.{axis}": ("twist.covariance", 6, 3 + at) for axis, at in _AXES.items()},
    "orientation:yaw": ("orientation_covariance", 3, 2),
    **{f"angular_velocity.{axis}": ("angular_velocity_covariance", 3, at) for axis, at in _AXES.items()},
    **{f"linear_acceleration.{axis}": ("linear_acceleration_covariance", 3, at) for axis, at in _AXES.items()},
}


def carried(model: m.Model, output: m.DomainOutput) -> tuple[m.Noise, ...]:
    """An output's noise, and for each field given none that is a state variable or a sensor
    read as it is (`distance = range_m`, no conversion to change its variance), that one's."""
    given = {field for n in output.noise for field in n.fields}
    found = list(output.noise)
    for field, expr in output.fields:
        if field in given or not isinstance(expr, m.Var) or expr.scope is not m.Scope.STATE:
            continue
        source = model.states.get(expr.name) or model.sensors.get(expr.name)
        if source is not None and source.noise is not None:
            found.append(m.Noise(field, source.noise.covariance, source.noise.deviation, source.noise.unit))
    return tuple(found)


def covariances(paths: list[tuple[m.AdapterField, str]], noise: tuple[m.Noise, ...]) -> tuple[tuple[str, m.Rows], ...]:
    """Each covariance of an output's message its noise fills (its path, its rows), in the order
    the table names them, given each field's path in the message (its adapter's in a framework);
    a field's noise of one value (a number's) on the diagonal, and a covariance over several
    fields (`noise (x, y, theta) [...]`) at their places, where two of them share a covariance of the
    message (the pose's x and y; not the pose's x and the twist's speed, which no member holds)."""
    found: dict[str, list[list[float]]] = {}
    where = {f.name: path for f, path in paths}
    for given in noise:
        if len(given.covariance) != len(given.fields):
            continue  # an array's: its values have no places of their own
        places = [DIAGONALS.get(where.get(field, "")) for field in given.fields]
        for i, row_place in enumerate(places):
            for j, column_place in enumerate(places):
                if row_place is None or column_place is None or row_place[0] != column_place[0]:
                    continue
                path, side, at = row_place
                rows = found.setdefault(path, [[0.0] * side for _ in range(side)])
                rows[at][column_place[2]] = given.covariance[i][j]
    ordered = list(dict.fromkeys(path for path, _, _ in DIAGONALS.values()))
    return tuple((path, tuple(tuple(row) for row in found[path])) for path in ordered if path in found)
