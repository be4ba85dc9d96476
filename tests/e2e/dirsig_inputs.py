# SPDX-License-Identifier: Apache-2.0
"""DIRSIG input files the end-to-end tests write: raw platform motion (.ppd), a one-task
snapshot tasks file and the .sim naming the inputs. Shared by render_units_test.py and
render_geometry_test.py."""


def ppd(entries, rotation_order="xyz"):
    """A raw .ppd in scene ENU: `entries` are (t_s, (x, y, z) m, (x, y, z) attitude in
    degrees, absolute Euler angles in `rotation_order`)."""
    rows = []
    for t, p, a in entries:
        rows.append(f"""\
    <entry>
      <datetime type="relative">{t}</datetime>
      <position><location type="scene"><point><x>{float(p[0])!r}</x><y>{float(p[1])!r}</y><z>{float(p[2])!r}</z></point></location></position>
      <orientation><eulerangles><cartesiantriple><x>{a[0]}</x><y>{a[1]}</y><z>{a[2]}</z></cartesiantriple></eulerangles></orientation>
    </entry>
""")
    return f"""<platformmotion type="generic">
  <method type="raw"/>
  <data rotationframe="sceneenu" rotationorder="{rotation_order}" angletype="absolute"
        angularunits="degrees" spatialunits="meters">
{''.join(rows)}  </data>
</platformmotion>
"""


def sim(scene, platform, motion, tasks="snapshot.tasks", atmosphere="none.atm.yaml"):
    """A DIRSIG4 .sim naming its inputs relative to itself."""
    return f"""<simulation>
  <scene                 externalfile="./{scene}"/>
  <atmosphericconditions externalfile="./{atmosphere}"/>
  <platform              externalfile="./{platform}"/>
  <platformmotion        externalfile="./{motion}"/>
  <tasklist              externalfile="./{tasks}"/>
</simulation>
"""


def snapshot_tasks(utc):
    """One task at the instant `utc` (ISO 8601 without the zone, read as UTC)."""
    return f"""<tasklist>
  <reference><datetime type="absolute">{utc}Z</datetime></reference>
  <task>
    <metadata><entry><name>Name</name><value><![CDATA[Snapshot]]></value></entry></metadata>
    <start><datetime type="relative">0</datetime></start>
    <stop><datetime type="relative">0</datetime></stop>
  </task>
</tasklist>
"""
