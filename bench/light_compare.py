# bench/light_compare.py: per-face and per-texture comparison of the style-0 lightmaps of two
# BSPs with the same geometry (e.g. sblight's relight of a map against ericw-tools' original).
# usage: python3 bench/light_compare.py ours.bsp reference.bsp
import struct,sys
def load(p):
    d=open(p,'rb').read()
    lumps=[struct.unpack_from('<ii',d,4+8*i) for i in range(15)]
    fo,fl=lumps[7]; lo,ll=lumps[8]
    L=d[lo:lo+ll]
    faces=[]
    for i in range(fl//20):
        pn,side,fe,ne,ti,s0,s1,s2,s3,lof=struct.unpack_from('<hhihhBBBBi',d,fo+20*i)
        faces.append((ti,(s0,s1,s2,s3),lof))
    offs=sorted(set(f[2] for f in faces if f[2]>=0))+[ll]
    nxt={offs[i]:offs[i+1] for i in range(len(offs)-1)}
    res=[]
    for ti,st,lof in faces:
        if lof<0: res.append(None); continue
        ns=sum(1 for s in st if s!=255)
        n=(nxt[lof]-lof)//max(ns,1)
        k=st.index(0) if 0 in st else 0  # the style-0 block (not always first in other compilers' output)
        b=L[lof+k*n:lof+(k+1)*n]
        res.append((sum(b)/max(len(b),1),len(b),st,ti))
    # texinfo -> miptex name
    to,tl=lumps[6]; mo,ml=lumps[2]
    names=[]
    nm=struct.unpack_from('<i',d,mo)[0]
    mofs=struct.unpack_from('<%di'%nm,d,mo+4)
    for o in mofs:
        names.append(d[mo+o:mo+o+16].split(b'\0')[0].decode('latin1') if o>=0 else '?')
    tex=[names[struct.unpack_from('<i',d,to+40*i+32)[0]] for i in range(tl//40)]
    return res,tex
a,ta=load(sys.argv[1]); b,tb=load(sys.argv[2])
sa=sb=n=0
rows=[]
for i,(x,y) in enumerate(zip(a,b)):
    if x is None or y is None: continue
    sa+=x[0]*x[1]; sb+=y[0]*y[1]; n+=x[1]
    rows.append((y[0]-x[0],i,x[0],y[0],x[1],ta[x[3]],x[2]))
print('weighted style-0 mean ericw',sb/n,'ours',sa/n)
rows.sort()
for r in rows[:15]: print('%.1f face %d ours %.1f ericw %.1f n %d %s %s'%r)
from collections import defaultdict
bytex=defaultdict(lambda:[0,0,0])
for r in rows:
    t=bytex[r[5]]; t[0]+=r[2]*r[4]; t[1]+=r[3]*r[4]; t[2]+=r[4]
print('by texture (largest deficit x samples):')
for k,v in sorted(bytex.items(), key=lambda kv:(kv[1][0]-kv[1][1]))[:12]: print(k, 'ours %.1f ericw %.1f n %d'%(v[0]/v[2],v[1]/v[2],v[2]))
