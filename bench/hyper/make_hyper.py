#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Writes an AVIRIS-like hyperspectral simulation into a folder (docs/performance.md,
# "Hyperspectral"): an imager of SIZE x SIZE pixels 1000 m above the render fixtures' plate
# and box (tests/data/render/scene.yaml), a bandpass of 0.4-2.5 um at 1 nm (2,101 samples)
# and 224 gaussian channels (10 nm FWHM, centres evenly spaced over 0.4-2.5 um), one capture.
# --samples N gives a bandpass of N samples over the same range instead (N = 2: the cheap
# reference the hyperspectral cost is compared with).
# Usage: make_hyper.py OUT [--size 256] [--samples 2101] [--channels 224]
import argparse
import os
import shutil

here = os.path.dirname(os.path.abspath(__file__))
render = os.path.join(here, '..', '..', 'tests', 'data', 'render')
ap = argparse.ArgumentParser()
ap.add_argument('out')
ap.add_argument('--size', type=int, default=256)
ap.add_argument('--samples', type=int, default=2101)
ap.add_argument('--channels', type=int, default=224)
a = ap.parse_args()
os.makedirs(a.out, exist_ok=True)
for f in ('scene.yaml', 'static.ppd'):
    shutil.copy(os.path.join(render, f), a.out)
open(os.path.join(a.out, 'atmosphere.yaml'), 'w').write('model: parametric\n')
open(os.path.join(a.out, 'one.tasks'), 'w').write('''<tasklist>
  <reference><datetime type="absolute">2020-06-21T12:00:00.0000-04:00</datetime></reference>
  <task>
    <start><datetime type="relative">0.0</datetime></start>
    <stop><datetime type="relative">0.0</datetime></stop>
  </task>
</tasklist>
''')
delta = 2.1 / (a.samples - 1)
channels = []
for i in range(a.channels):
    centre = 0.405 + i * (2.49 - 0.405) / max(1, a.channels - 1)
    channels.append('<channel name="b%03d" shape="gaussian"><center>%.5f</center>'
                    '<width>0.010</width></channel>' % (i, centre))
# The focal length makes the 1000 m footprint about 10 m wide whatever the size.
pixel_um = 20.0
focal_mm = 1000.0 * a.size * pixel_um * 1e-3 / 10.0
open(os.path.join(a.out, 'hyper.platform'), 'w').write('''<platform>
  <clocktable/>
  <attachment>
    <affinetransform/>
    <instrument name="Imager" type="generic">
      <properties><focallength>%.6f</focallength></properties>
      <focalplane enabled="true" name="HSI">
        <capturemethod type="simple" name="Simple">
          <imagefile areaunits="cm2" fluxunits="watts">
            <basename>hsi</basename><extension>img</extension><schedule>capture</schedule>
          </imagefile>
          <spectralresponse>
            <bandpass spectralunits="microns">
              <minimum>0.4</minimum><maximum>2.5</maximum><delta>%.12g</delta>
            </bandpass>
            <channellist>
              %s
            </channellist>
          </spectralresponse>
          <temporalintegration tdi="false"><time>0</time></temporalintegration>
        </capturemethod>
        <detectorarray spatialunits="microns">
          <clock type="independent" temporalunits="hertz"><rate>1</rate><offset>0</offset></clock>
          <xelementcount>%d</xelementcount><yelementcount>%d</yelementcount>
          <xelementsize>%g</xelementsize><yelementsize>%g</yelementsize>
          <xelementspacing>%g</xelementspacing><yelementspacing>%g</yelementspacing>
        </detectorarray>
      </focalplane>
    </instrument>
  </attachment>
</platform>
''' % (focal_mm, delta, '\n              '.join(channels), a.size, a.size, pixel_um, pixel_um,
       pixel_um, pixel_um))
open(os.path.join(a.out, 'hyper.jsim'), 'w').write('''[{
  "scene_list": [{"inputs": "scene.yaml"}],
  "plugin_list": [
    {"name": "BasicAtmosphere", "inputs": {"atmosphere_filename": "atmosphere.yaml"}},
    {"name": "BasicPlatform", "inputs": {"platform_filename": "hyper.platform",
      "motion_filename": "static.ppd", "tasks_filename": "one.tasks"}}
  ]
}]
''')
