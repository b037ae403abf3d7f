# steps_tail_map.py IN.s OUT.s HEADER FIRST: writes order_search.py's order OUT.s of IN.s (a body of
# steps_k3v_pass's asm lines FIRST .. as bench/count.sh dumps them, its last line the compiler's branch)
# back onto HEADER's asm lines (asm/span_persp_a64mid.h), matched by their text.
# mapback.py IN.s OUT.s HEADER first_asm_index : reorders the header's asm lines [first, first+len(IN)) as OUT orders IN
import sys,re
inp=[l.strip() for l in open(sys.argv[1]) if l.strip()]
out=[l.strip() for l in open(sys.argv[2]) if l.strip()]
hdr=sys.argv[3]; first=int(sys.argv[4])
H=open(hdr).read().split('\n')
b=next(i for i,l in enumerate(H) if 'BEGIN steps_k3v_pass' in l)
e=next(i for i,l in enumerate(H) if 'END steps_k3v_pass' in l)
asm=[i for i in range(b+1,e) if H[i].strip().startswith('"')]
assert len(asm)==333, len(asm)
# the body's last line is the compiler's branch (not in the asm)
n=len(inp)-1
assert out[-1]==inp[-1]
idx=asm[first:first+n]
used=[False]*n; perm=[]
for l in out[:-1]:
    k=next(k for k in range(n) if not used[k] and inp[k]==l); used[k]=True; perm.append(k)
texts=[H[i].strip() for i in idx]
def body(t): return t.rstrip(',').strip('"').replace('\\n\\t','').replace('\\n','')
new=[texts[k] for k in perm]
# keep the line endings: the last asm line has no \n\t
last_noterm = not texts[-1].endswith('\\n\\t"')
new=[('"'+body(t)+'\\n\\t"') for t in new]
if last_noterm: new[-1]='"'+body(new[-1])+'"'
ind=re.match(r'\s*',H[idx[0]]).group(0)
for i,t in zip(idx,new): H[i]=ind+t
open(hdr,'w').write('\n'.join(H))
print('moved', sum(1 for a,k in enumerate(perm) if a!=k))
