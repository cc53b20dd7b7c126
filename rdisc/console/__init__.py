"""`rdisc console`: a local web page to bring up and exercise a device (thesis ch. 5).

`page.render` writes the page from the Model; `server.Console` serves it with its assets
(assets/console.js and console.css, shipped in the package: nothing comes from the
internet) and pushes to every open page, over a WebSocket, what happens as it happens:

    {"type": "hello", "state": {...}, "sensor_ages": {...}, "trace": [io...], "errors": [error...], "outputs": [output...]}
    {"type": "output", "t": S, "name": O, "contents": {FIELD: value}}
    {"type": "io", "t": S, "direction": "write" | "read" | "lines", "connection": C, "data": "89 00 c8"}
    {"type": "state", "state": {NAME: value}, "sensor_ages": {SENSOR: seconds | null}}
    {"type": "error", "t": S, "error": TYPE, "message": TEXT}
    {"type": "result", "id": N, "ok": true} / {..., "ok": false, "error": TYPE, "message": TEXT}
    {"type": "body", "t": S, "links": {LINK: [x, y, z, qw, qx, qy, qz]}, "joints": {JOINT: position}}

the last (`--sim` only) ten times a second while a page is open: each link's frame in the
world (m, and a unit quaternion) and each moving joint's position (rad or m), as the
simulation has them (`rdisc.sim.Simulation.link_poses`); the page draws the body from them. The server takes the page's calls, `{"id": N, "kind": "input" | "interface" | "primitive",
"name": NAME, "values": {NAME: text}}`, each value the text of its form field (a checkbox's
a bool), made the parameter's type here. `sensor_ages` (only for a description with sensors): seconds since
each sensor's value was read, by the robot's clock, null before its first read; the state is
pushed again when a sensor is read anew. `t` is seconds since the console started;
bytes are hex, as `rdisc run --trace` prints them.
"""

PING_S = 5.0
"""Seconds: how often the console pings each page, and how long a page has to answer (and to close
once closed): a page that does not is gone, and when it was the last the terminate hooks run
(`rdisc console --ping`)."""
