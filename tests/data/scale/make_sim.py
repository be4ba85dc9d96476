#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Writes a small simulation for the sharding, row and merge tests into a folder: the render
# fixtures' 8 x 6 camera over scene.yaml (tests/data/render), three captures at 10 Hz, a
# parametric atmosphere, a GeoLocation truth collection and a detector model (counts), with
# the image file schedule given (capture: one file per capture; simulation: one file of all).
# Usage: make_sim.py WORK [--schedule capture|simulation] [--no-truth] [--no-detector]
#                         [--atmosphere none|parametric]
import argparse
import os
import shutil

here = os.path.dirname(os.path.abspath(__file__))
render = os.path.join(here, '..', 'render')
ap = argparse.ArgumentParser()
ap.add_argument('work')
ap.add_argument('--schedule', default='capture', choices=['capture', 'simulation'])
ap.add_argument('--no-truth', action='store_true')
ap.add_argument('--no-detector', action='store_true')
ap.add_argument('--atmosphere', default='parametric', choices=['none', 'parametric'])
args = ap.parse_args()
os.makedirs(args.work, exist_ok=True)
for f in ('scene.yaml', 'static.ppd', 'three.tasks', 'one.jsim'):
    shutil.copy(os.path.join(render, f), args.work)
with open(os.path.join(args.work, 'none.atm.yaml'), 'w') as f:
    f.write('model: %s\n' % args.atmosphere)
text = open(os.path.join(render, 'cam.platform')).read()
text = text.replace('<schedule>simulation</schedule>', '<schedule>%s</schedule>' % args.schedule)
text = text.replace('<focallength>100</focallength>',
                    '<focallength>100</focallength><aperturediameter>0.02</aperturediameter>')
text = text.replace('<time>0</time>', '<time>0.001</time>')
if not args.no_detector:
    text = text.replace(
        '</temporalintegration>',
        '</temporalintegration><detectormodel><quantumefficiency>0.8</quantumefficiency>'
        '<readnoise>5</readnoise><minelectrons>0</minelectrons><maxelectrons>100000'
        '</maxelectrons><bitdepth>12</bitdepth></detectormodel>')
if not args.no_truth:
    text = text.replace(
        '<detectorarray',
        '<truthcollection name="t"><imagefile><basename>truth</basename><schedule>%s</schedule>'
        '</imagefile><collectorlist><collector><name>GeoLocation</name></collector>'
        '<collector><name>Material</name></collector></collectorlist></truthcollection>\n'
        '        <detectorarray' % args.schedule)
with open(os.path.join(args.work, 'cam.platform'), 'w') as f:
    f.write(text)
