#!/usr/bin/env python3
"""Writes src/builtins/sysvars.tsv: AutoCAD's system variables as data (name, type, default,
flags). The drawing-stored ones come from ezdxf's header-variable table (MIT); the others
(session, registry and read-only variables) are listed below from AutoCAD's reference.
Flags: hdr (stored in the DXF header), ro (read-only), lo..hi (integer/real range),
pos (real > 0), nonneg (real >= 0). Run with the tests' venv: .venv/bin/python scripts/gen_sysvars.py
"""
import os
import ezdxf.sections.headervars as h

SKIP = {'$REQUIREDVERSIONS', '$ACADMAINTVER', '$HANDLING', '$FINGERPRINTGUID',
        '$VERSIONGUID', '$INTERFEREOBJVS', '$INTERFEREVPVS', '$CMATERIAL'}
RENAME = {'$MENU': 'MENUNAME'}
READ_ONLY = {'ACADVER', 'TDCREATE', 'TDUCREATE', 'TDUPDATE', 'TDUUPDATE', 'TDINDWG',
             'TDUSRTIMER', 'EXTMIN', 'EXTMAX', 'HANDSEED', 'UCSORG', 'UCSXDIR', 'UCSYDIR',
             'UCSNAME', 'PEXTMIN', 'PEXTMAX', 'MENUNAME', 'LASTSAVEDBY', 'PUCSNAME',
             'PUCSORG', 'PUCSXDIR', 'PUCSYDIR'}
# lispcad's deliberate defaults where they differ from ezdxf's (tests list them too).
DEFAULTS = {'INSUNITS': '4', 'OSMODE': '0', 'LASTSAVEDBY': 'lispcad', 'AUPREC': '0',
            'DIMZIN': '0', 'ACADVER': 'AC1032'}

# Variables that are not in the DXF header: (name, type, default, flags).
SESSION = """
ACADLSPASDOC int 0
ACADPREFIX str  ro
ACADVER str 24.3s (lispcad) ro
AFLAGS int 16
APERTURE int 10 1..50
AREA real 0.0 ro
ATTIPE int 0 0..1
AUDITCTL int 0 0..1
AUTOSNAP int 63 0..63
BACKZ real 0.0 ro
BINDTYPE int 0 0..1
BLIPMODE int 0 0..1
CAMTOL real 0.01 pos
CDATE real 0.0 ro
CENTERMT int 0 0..1
CHAMMODE int 0 0..1
CHORDTOL real 0.01 pos
CIRCLERAD real 0.0 nonneg
CMDACTIVE int 0 ro
CMDDIA int 1 0..1
CMDECHO int 1 0..1
CMDNAMES str  ro
CPLOTSTYLE str ByColor
CTAB str Model ro
CURSORSIZE int 5 1..100
CVPORT int 2
DATE real 0.0 ro
DBMOD int 0 ro
DCTCUST str 
DCTMAIN str enu
DEFLPLSTYLE str 
DEFPLSTYLE str 
DELOBJ int 3 -3..3
DEMANDLOAD int 3 0..3
DIASTAT int 1 ro
DISTANCE real 0.0 ro
DONUTID real 0.5 nonneg
DONUTOD real 1.0 pos
DRAGP1 int 10 0..32767
DRAGP2 int 25 0..32767
DWGCHECK int 0 0..3
DWGNAME str Drawing1.dwg ro
DWGPREFIX str  ro
DWGTITLED int 0 ro
DXFPROFILE str CAD
EDGEMODE int 0 0..1
ERRNO int 0
EXPERT int 0 0..5
EXPLMODE int 1 0..1
FACETRES real 0.5 0.01..10
FIELDDISPLAY int 1 0..1
FILEDIA int 1 0..1
FONTALT str simplex.shx
FONTMAP str acad.fmp
FRONTZ real 0.0 ro
GEOMTOL real 1e-09 pos
BENDDEV real 0.0 ro
GRIDMODE int 0 0..1
GRIDUNIT pt2 10.0 10.0
GRIPS int 2 0..2
GRIPSIZE int 5 1..255
HIGHLIGHT int 1 0..1
HPANG real 0.0
HPASSOC int 1 0..1
HPBOUND int 1 0..1
HPDOUBLE int 0 0..1
HPGAPTOL real 0.0 0..5000
HPNAME str ANSI31
HPSCALE real 1.0 pos
HPSPACE real 1.0 pos
IMAGEHLT int 0 0..1
ISOLINES int 4 0..2047
LASTANGLE real 0.0 ro
LASTPOINT pt3 0.0 0.0 0.0
LASTPROMPT str  ro
LISPSYS int 1 0..2
LOCALE str ENU ro
LOGFILEMODE int 0 0..1
LOGFILENAME str  ro
LOGINNAME str  ro
LTGAPSELECTION int 1 0..1
MAXSORT int 1000 0..32767
MBUTTONPAN int 1 0..1
MENUECHO int 0 0..15
MILLISECS int 0 ro
MODEMACRO str 
MTEXTED str Internal
MTJIGSTRING str abc
NOMUTT int 0 0..1
OFFSETDIST real -1.0
OFFSETGAPTYPE int 0 0..2
OSNAPCOORD int 2 0..2
OSNAPZ int 0 0..1
PAPERUPDATE int 0 0..1
PEDITACCEPT int 0 0..1
PELLIPSE int 0 0..1
PERIMETER real 0.0 ro
PICKADD int 2 0..2
PICKAUTO int 5 0..7
PICKBOX int 3 0..50
PICKDRAG int 2 0..2
PICKFIRST int 1 0..1
PICKSTYLE int 1 0..3
PLATFORM str  ro
PLINETYPE int 2 0..2
PLOTROTMODE int 2 0..2
POLARADDANG str 
POLARANG real 1.5707963267949
POLARDIST real 0.0 nonneg
POLARMODE int 0 0..15
POLYSIDES int 4 3..1024
POPUPS int 1 ro
PRODUCT str lispcad ro
PROGRAM str lispcad ro
PROJMODE int 1 0..2
PSTYLEPOLICY int 1 0..1
QAFLAGS int 0 0..32767
RASTERPREVIEW int 1 0..1
REMEMBERFOLDERS int 1 0..1
REPORTERROR int 0 0..1
ROLLOVERTIPS int 1 0..1
SAVEFILE str  ro
SAVEFILEPATH str 
SAVENAME str  ro
SAVETIME int 10 0..600
SCREENBOXES int 0 ro
SCREENMODE int 3 ro
SCREENSIZE pt2 1280.0 800.0 ro
SDI int 0 0..3
SELECTIONAREA int 1 0..1
SHORTCUTMENU int 11 0..31
SNAPANG real 0.0
SNAPBASE pt2 0.0 0.0
SNAPISOPAIR int 0 0..2
SNAPMODE int 0 0..1
SNAPSTYL int 0 0..1
SNAPTYPE int 0 0..1
SNAPUNIT pt2 10.0 10.0
SOLIDCHECK int 1 0..1
SPLDEGREE int 3 1..5
SPLKNOTS int 0 0..2
SPLMETHOD int 0 0..1
SYSCODEPAGE str ANSI_1252 ro
TABMODE int 0 0..1
TARGET pt3 0.0 0.0 0.0 ro
TEMPPREFIX str  ro
TEXTEVAL int 0 0..1
TEXTFILL int 1 0..1
TEXTQLTY int 50 0..100
TOOLTIPS int 1 0..1
TRACKPATH int 0 0..3
TRIMMODE int 1 0..1
TSPACEFAC real 1.0 0.25..4
TSPACETYPE int 1 1..2
TSTACKALIGN int 1 0..2
TSTACKSIZE int 70 25..125
UCSAXISANG int 90 5..180
UCSFOLLOW int 0 0..1
UCSICON int 3 0..3
UCSVIEW int 1 0..1
UCSVP int 1 0..1
UNDOCTL int 21 ro
UNDOMARKS int 0 ro
UPDATETHUMBNAIL int 15 0..31
USERS1 str 
USERS2 str 
USERS3 str 
USERS4 str 
USERS5 str 
VIEWCTR pt3 0.0 0.0 0.0 ro
VIEWDIR pt3 0.0 0.0 1.0
VIEWMODE int 0 ro
VIEWSIZE real 297.0 ro
VIEWTWIST real 0.0 ro
VSMAX pt3 0.0 0.0 0.0 ro
VSMIN pt3 0.0 0.0 0.0 ro
WHIPARC int 0 0..1
WMFBKGND int 0 0..1
WORLDUCS int 1 ro
WRITESTAT int 1 ro
XFADECTL int 50 0..90
XLOADCTL int 2 0..2
XLOADPATH str 
XREFCTL int 0 0..1
ZOOMFACTOR int 60 3..100
ZOOMWHEEL int 0 0..1
"""

# Ranges of drawing-stored variables.
RANGES = {
    'LUNITS': '1..5', 'LUPREC': '0..8', 'AUNITS': '0..4', 'AUPREC': '0..8', 'ANGDIR': '0..1',
    'ATTDIA': '0..1', 'ATTREQ': '0..1', 'ATTMODE': '0..2', 'COORDS': '0..3',
    'DIMZIN': '0..15', 'DIMDEC': '0..8', 'DIMTDEC': '0..8', 'DIMADEC': '-1..8',
    'DIMALTD': '0..8', 'DIMALTTD': '0..8', 'DIMTAD': '0..4', 'DIMJUST': '0..4',
    'DIMLUNIT': '1..6', 'DIMAUNIT': '0..4', 'DIMATFIT': '0..3', 'DIMFRAC': '0..2',
    'DIMTMOVE': '0..2', 'DIMASSOC': '0..2', 'DRAGMODE': '0..2', 'FILLMODE': '0..1',
    'INSUNITS': '0..24', 'MEASUREMENT': '0..1', 'MIRRTEXT': '0..1', 'ORTHOMODE': '0..1',
    'OSMODE': '0..32767', 'PDMODE': '0..100', 'PLINEGEN': '0..1', 'PSLTSCALE': '0..1',
    'QTEXTMODE': '0..1', 'REGENMODE': '0..1', 'SPLFRAME': '0..1', 'SPLINETYPE': '5..6',
    'SPLINESEGS': '-32768..32767', 'SURFTAB1': '2..32766', 'SURFTAB2': '2..32766',
    'SURFTYPE': '5..8', 'SURFU': '0..200', 'SURFV': '0..200', 'TILEMODE': '0..1',
    'UNITMODE': '0..1', 'USRTIMER': '0..1', 'VISRETAIN': '0..1', 'LIMCHECK': '0..1',
    'PLIMCHECK': '0..1', 'SKPOLY': '0..2', 'WORLDVIEW': '0..1', 'PSTYLEMODE': '0..1',
    'LWDISPLAY': '0..1', 'XEDIT': '0..1', 'EXTNAMES': '0..1', 'PROXYGRAPHICS': '0..1',
    'SHADEDGE': '0..3', 'SHADEDIF': '0..100', 'MAXACTVP': '2..64', 'CMLJUST': '0..2',
    'TEXTSIZE': 'pos', 'DIMSCALE': 'nonneg', 'LTSCALE': 'pos', 'CELTSCALE': 'pos',
    'DIMTXT': 'pos', 'DIMASZ': 'nonneg', 'FILLETRAD': 'nonneg', 'TRACEWID': 'nonneg',
    'PLINEWID': 'nonneg', 'SKETCHINC': 'pos', 'DIMLFAC': 'pos', 'DIMTFAC': 'pos',
    'CMLSCALE': 'nonneg', 'LENSLENGTH': 'pos', 'PDSIZE': None,
}


def main():
    rows = {}
    for k, v in h.HEADER_VAR_MAP.items():
        if k in SKIP:
            continue
        name = RENAME.get(k, k[1:])
        c, d = v.code, v.default
        if name == 'CECOLOR':
            t, d = 'str', 'BYLAYER'
        elif name == 'INTERFERECOLOR':
            t, d = 'str', '1'
        elif name == 'CELTYPE':
            t, d = 'str', 'BYLAYER'
        elif c == 10:
            t, d = 'pt%d' % len(d), ' '.join(repr(float(x)) for x in d)
        elif c in (40, 50):
            t, d = 'real', repr(float(d))
        elif c in (1, 2, 3, 5, 6, 7, 8):
            t = 'str'
        else:
            t = 'int'
        d = DEFAULTS.get(name, d)
        flags = ['hdr']
        if name in READ_ONLY:
            flags.append('ro')
        if RANGES.get(name):
            flags.append(RANGES[name])
        rows[name] = (t, str(d), flags)
    for line in SESSION.strip('\n').split('\n'):
        name, t, rest = line.split(' ', 2)
        parts = rest.split(' ')
        flags = [p for p in parts if p == 'ro' or '..' in p or p in ('pos', 'nonneg')]
        value = ' '.join(parts[:len(parts) - len(flags)]) if flags else rest
        old = rows.get(name)
        if old:  # a header variable the session list refines (ACADVER's text)
            rows[name] = (t, value.strip(), sorted(set(old[2] + flags), key=old[2].__contains__, reverse=True))
        else:
            rows[name] = (t, value.strip(), flags)
    out = os.path.join(os.path.dirname(__file__), '..', 'src', 'builtins', 'sysvars.tsv')
    with open(out, 'w', encoding='utf-8') as f:
        f.write('# AutoCAD system variables: NAME<TAB>TYPE<TAB>DEFAULT<TAB>FLAGS. '
                'Generated by scripts/gen_sysvars.py.\n')
        for name in sorted(rows):
            t, d, flags = rows[name]
            f.write(f"{name}\t{t}\t{d}\t{' '.join(flags)}\n")
    print(len(rows), 'variables')


main()
