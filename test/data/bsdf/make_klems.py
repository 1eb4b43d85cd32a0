#!/usr/bin/env python3
"""Writes prism_quarter.xml: a made-up prismatic pane as an LBNL/WINDOW BSDF on the Klems quarter basis
(41 patches), for Brume's tests. Transmission is a lobe about the straight-through direction bent 17°
upward (toward +y of the BSDF frame, the up vector) on a diffuse floor; reflection is a blurred mirror
lobe on a diffuse floor, different on each side. The back transmission is the front one's reciprocal.
Directions follow Radiance's bsdf_m.c conventions (see lib/material/klems_basis.h)."""
import math

BOUNDS = [0, 9, 27, 45, 63, 90]
PHIS = [1, 8, 12, 12, 8]
PATCHES = [(r, k) for r in range(len(PHIS)) for k in range(PHIS[r])]


def centre(p):  # front outgoing direction at the patch centre
    r, k = PATCHES[p]
    theta = 0 if r == 0 else math.radians((BOUNDS[r] + BOUNDS[r + 1]) / 2)
    phi = 2 * math.pi * k / PHIS[r]
    return (math.cos(phi) * math.sin(theta), math.sin(phi) * math.sin(theta), math.cos(theta))


def index(v):  # front outgoing patch of v (z >= 0)
    theta = math.degrees(math.acos(min(1, v[2])))
    phi = math.degrees(math.atan2(v[1], v[0])) % 360
    first = 0
    for r, n in enumerate(PHIS):
        if theta < BOUNDS[r + 1]:
            return first + int(phi / 360 * n + 0.5) % n
        first += n
    raise ValueError(v)


def ohm(p):
    r, _ = PATCHES[p]
    c0, c1 = math.cos(math.radians(BOUNDS[r])), math.cos(math.radians(BOUNDS[r + 1]))
    return math.pi * (c0 * c0 - c1 * c1) / PHIS[r]


def angle(a, b):
    return math.acos(max(-1, min(1, sum(x * y for x, y in zip(a, b)))))


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return tuple(x / n for x in v)


def lobe(total, sigma, floor, target):
    """Matrix [o][i]: for each incident patch, `total` spread about target(centre of i) plus `floor`."""
    n = len(PATCHES)
    m = [[0.0] * n for _ in range(n)]
    for i in range(n):
        t = target(centre(i))
        k = [math.exp(-angle(centre(o), t) ** 2 / (2 * sigma ** 2)) for o in range(n)]
        s = sum(k[o] * ohm(o) for o in range(n))
        for o in range(n):
            m[o][i] = total * math.cos(math.radians(BOUNDS[PATCHES[i][0]])) ** 0.5 * k[o] / s + floor
    return m


def bent(v):  # travel straight through, bent toward +y; in the out basis's own (front) coordinates
    return unit((v[0], v[1] + 0.3, v[2]))


def mirror(v):
    return v


# In basis coordinates both transmission and mirror reflection keep the patch: targets are the centres.
transmit_front = lobe(0.4, math.radians(15), 0.03, bent)
reflect_front = lobe(0.08, math.radians(10), 0.05, mirror)
reflect_back = lobe(0.2, math.radians(12), 0.01, mirror)


def rotated(p):  # the patch half way round in azimuth
    x, y, z = centre(p)
    return index((-x, -y, z))


n = len(PATCHES)
# Reciprocity: light in through the back at b, out the front at a, as light in at a, out at b.
transmit_back = [[transmit_front[rotated(i)][rotated(o)] for i in range(n)] for o in range(n)]
for name, m in [("Tf", transmit_front), ("Tb", transmit_back), ("Rf", reflect_front), ("Rb", reflect_back)]:
    print(name, "max hemispherical", round(max(sum(m[o][i] * ohm(o) for o in range(n)) for i in range(n)), 4))
for r, t in [(reflect_front, transmit_front), (reflect_back, transmit_back)]:
    print("max reflected + transmitted", round(max(sum((r[o][i] + t[o][i]) * ohm(o) for o in range(n)) for i in range(n)), 4))


def block(direction, m):
    rows = "\n".join(" ".join("%.6g" % m[o][i] for i in range(n)) for o in range(n))
    return f"""		<WavelengthDataBlock>
			<WavelengthDataDirection>{direction}</WavelengthDataDirection>
			<ColumnAngleBasis>LBNL/Klems Quarter</ColumnAngleBasis>
			<RowAngleBasis>LBNL/Klems Quarter</RowAngleBasis>
			<ScatteringDataType>BTDF</ScatteringDataType>
			<ScatteringData>
{rows}
			</ScatteringData>
		</WavelengthDataBlock>
"""


basis = "".join(f"""			<AngleBasisBlock>
				<Theta>{0 if r == 0 else (BOUNDS[r] + BOUNDS[r + 1]) / 2:g}</Theta>
				<nPhis>{PHIS[r]}</nPhis>
				<ThetaBounds>
					<LowerTheta>{BOUNDS[r]}</LowerTheta>
					<UpperTheta>{BOUNDS[r + 1]}</UpperTheta>
				</ThetaBounds>
			</AngleBasisBlock>
""" for r in range(len(PHIS)))

# WINDOW's front is Radiance's back: "Transmission Front" is light arriving on Radiance's back side.
with open("prism_quarter.xml", "w") as f:
    f.write(f"""<?xml version="1.0" encoding="UTF-8"?>
<!-- Made by Brume's test/data/bsdf/make_klems.py: a made-up prismatic pane, for tests only. -->
<WindowElement xmlns="http://windows.lbl.gov" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="http://windows.lbl.gov/BSDF-v1.4.xsd">
<WindowElementType>System</WindowElementType>
<FileType>BSDF</FileType>
<Optical>
<Layer>
	<Material>
		<Name>Brume test prism</Name>
		<DeviceType>Other</DeviceType>
	</Material>
	<DataDefinition>
		<IncidentDataStructure>Columns</IncidentDataStructure>
		<AngleBasis>
			<AngleBasisName>LBNL/Klems Quarter</AngleBasisName>
{basis}		</AngleBasis>
	</DataDefinition>
	<WavelengthData>
		<LayerNumber>System</LayerNumber>
		<Wavelength unit="Integral">Visible</Wavelength>
		<SourceSpectrum>CIE Illuminant D65 1nm.ssp</SourceSpectrum>
		<DetectorSpectrum>ASTM E308 1931 Y.dsp</DetectorSpectrum>
{block("Transmission Front", transmit_back)}{block("Transmission Back", transmit_front)}{block("Reflection Front", reflect_back)}{block("Reflection Back", reflect_front)}	</WavelengthData>
</Layer>
</Optical>
</WindowElement>
""")
