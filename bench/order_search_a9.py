#!/usr/bin/env python3
# bench/order_search_a9.py: searches an instruction order of one straight-line Thumb-2 + NEON
# block against llvm-mca's Cortex-A9 model (as bench/count.sh times armhf blocks).
#
#   order_search_a9.py IN.s OUT.s [EVALS] [--runs]
#
# --runs: IN.s is a hot block of the ARMv7 50 .. 64 px spans as bench/count.sh dumps it
# (SB_MCA_DUMP); only the lines of a run's asm statement move, within it (a run: from a
# smulbt through the pixel groups and the VFP / NEON lines among and after them); the
# compiler's code between runs stays.
# IN.s: one instruction a line (no IT: a conditional move that an IT block guards is written
# unconditionally with the comment `@flags`, which makes it read the flags). Memory: loads and
# stores keep their order unless both carry different tags (`@m=NAME`); ldrb (texel gathers)
# move freely. s-register writes read their d register (partial writes). Each step moves one
# instruction to a random legal position and keeps the order if llvm-mca times it no slower.
# A model search: check the result with the tests. (Used for the ARMv7 50 .. 64 px prologue,
# asm/span_persp_v7mid.h.)
import re,sys,random,subprocess
ALIAS={'sl':'r10','fp':'r11','ip':'r12','sb':'r9'}
def regs_of(tok):
    tok=ALIAS.get(tok,tok)
    m=re.fullmatch(r'r(\d+)|lr|sp',tok)
    if m: return {tok}
    m=re.fullmatch(r'q(\d+)',tok)
    if m:
        n=int(m.group(1)); return {f'd{2*n}',f'd{2*n+1}'}
    m=re.fullmatch(r'd(\d+)(\[\d\])?',tok)
    if m: return {f'd{m.group(1)}'}
    m=re.fullmatch(r's(\d+)',tok)
    if m: return {f'd{int(m.group(1))//2}'}
    return set()
ACC=('vsra','vmla','vmlal','vbsl','vsri','vsli','mla','vmov.32','uxtah','vbit','vbif')
def parse(l):
    fl='@flags' in l
    mt=re.search(r'@m=(\w+)',l)
    l=l.split('@')[0]
    op,_,rest=l.strip().partition(' ')
    # expand d ranges {d0-d3}
    def rng(m):
        a,b=int(m.group(1)),int(m.group(2)); return ','.join(f'd{i}' for i in range(a,b+1))
    rest=re.sub(r'd(\d+)-d(\d+)',rng,rest)
    toks=re.findall(r'[a-z]+\d*(?:\[\d\])?',rest)
    toks=[t for t in toks if regs_of(t)]
    memm=re.search(r'\[([^\]]*)\]',rest)
    post='!' in rest
    rd=set();wr=set()
    allr=[regs_of(t) for t in toks]
    base=op.split('.')[0]
    is_store=base in('str','strd','strb','vst1','vstr','strh')
    is_load=base in('ldr','ldrd','ldrb','vld1','vldr','ldrh')
    if memm:
        inside=set().union(*[regs_of(t) for t in re.findall(r'[a-z]+\d*',memm.group(1))]) if re.findall(r'[a-z]+\d*',memm.group(1)) else set()
    else: inside=set()
    if is_store:
        rd=set().union(*allr) if allr else set()
        if post: wr|=inside
    elif is_load:
        outside=re.sub(r'\[[^\]]*\]','',rest)
        outs=[regs_of(t) for t in re.findall(r'[a-z]+\d*(?:\[\d\])?',outside) if regs_of(t)]
        wr=set().union(*outs) if outs else set(); rd=inside
        if post: wr|=inside
    elif False:
        pass
    elif base in('cmp','tst'):
        rd=set().union(*allr); wr={'flags'}
    elif base in('vcmp','vcmpe'):
        rd=set().union(*allr); wr={'fpscr'}
    elif base=='vmrs':
        rd={'fpscr'}; wr={'flags'}
    else:
        if allr:
            wr=set(allr[0]); rd=set().union(*allr[1:]) if len(allr)>1 else set()
            if base in ('vmov','vdup') and op.startswith('vmov') and len(allr)==3 and toks[0].startswith('r'):
                wr=allr[0]|allr[1]; rd=allr[2]
            if any(op.startswith(a) for a in ACC): rd|=allr[0]
        if re.fullmatch(r'[a-z]+(eq|ne|le|lt|ge|gt|ls|hi|cs|cc|mi|pl)(\.\w+)?',op) and base not in ('vcvt','vmull','vabs','vshl','vmul','vtst','vcgt','vcge','vmovl','vqmovn') : rd|={'flags'}|wr
        # s-register writes are partial: read the d too
        if toks and toks[0].startswith('s'): rd|=allr[0]
    if fl: rd=rd|{'flags'}
    mem=None
    if is_store or is_load:
        # texel loads (ldrb) are free; others ordered
        mem='free' if base=='ldrb' else ('st' if is_store else 'ld')
        if mt and mem!='free': mem=mem+':'+mt.group(1)
    if 'flags' in rest: pass
    return rd,wr,mem
def deps_ok(lines,P):
    pass
def build(lines):
    info=[parse(l) for l in lines]
    n=len(lines)
    # dependency edges i<j must stay
    pred=[set() for _ in range(n)]
    for j in range(n):
        rj,wj,mj=info[j]
        for i in range(j):
            ri,wi,mi=info[i]
            if (wi&rj) or (wi&wj) or (ri&wj): pred[j].add(i)
            elif mi and mj and mi!='free' and mj!='free' and (mi.startswith('st') or mj.startswith('st')):
                ti=mi.split(':')[1] if ':' in mi else None; tj=mj.split(':')[1] if ':' in mj else None
                if ti is None or tj is None or ti==tj: pred[j].add(i)
    return pred
def mca(lines,it=100):
    text=".syntax unified\n.thumb\n"+"\n".join(lines)+"\n"
    r=subprocess.run(["llvm-mca-14","-mtriple=thumbv7-linux-gnueabihf","-mcpu=cortex-a9","-mattr=+neon,+vfp4",f"-iterations={it}"],input=text,capture_output=True,text=True)
    m=re.search(r"Total Cycles:\s+(\d+)",r.stdout)
    if not m: raise SystemExit(r.stderr[:400])
    return int(m.group(1))/it
def search(lines,evals=1500,seed=1,fixed_head=0,out=None,fixed_tail=None):
    random.seed(seed)
    n=len(lines); pred=build(lines)
    succ=[set() for _ in range(n)]
    for j in range(n):
        for i in pred[j]: succ[i].add(j)
    order=list(range(n)); best=mca([lines[i] for i in order]); print('start',best,flush=True)
    for e in range(evals):
        pos={k:p for p,k in enumerate(order)}
        k=random.randrange(n)
        if pos[k]<fixed_head: continue
        lo=max([pos[i] for i in pred[k]],default=-1)+1; lo=max(lo,fixed_head)
        hi=min([pos[i] for i in succ[k]],default=n)-1
        if fixed_tail is not None:
            if pos[k]>=fixed_tail: continue
            hi=min(hi,fixed_tail-1)
        if hi<=lo: continue
        t=random.randint(lo,hi)
        if t==pos[k]: continue
        o=order[:]; o.remove(k); o.insert(t,k)
        c=mca([lines[i] for i in o])
        if c<=best:
            if c<best: print(e,c,flush=True)
            best=c; order=o
            if out: open(out,'w').write("\n".join(lines[i] for i in order)+"\n")
    return [lines[i] for i in order],best
PIX = ('smulbt', 'uxtah', 'add', 'ldrb', 'orr', 'str')


def run_regions(lines):
    """Per line: the index of its run statement, or -1 (fixed)."""
    n = len(lines)
    reg = [-1] * n
    r = -1
    i = 0
    while i < n:
        if lines[i].startswith('smulbt') and (r < 0 or reg[i - 1] != r):
            r += 1
            j = i
            last = i
            while j < n:
                op = lines[j].split()[0].split('.')[0]
                if op in PIX or lines[j].startswith('v'):
                    if op == 'str' or lines[j].startswith('v'):
                        last = j
                    j += 1
                else:
                    break
            for k in range(i, last + 1):
                reg[k] = r
            i = last + 1
        else:
            i += 1
    return reg


def search_runs(lines, evals, seed, out):
    random.seed(seed)
    reg = run_regions(lines)
    n = len(lines)
    pred = build(lines)
    succ = [set() for _ in range(n)]
    for j in range(n):
        for i in pred[j]:
            succ[i].add(j)
    order = list(range(n))
    best = mca(lines)
    print('start', best, flush=True)
    for e in range(evals):
        pos = {k: p for p, k in enumerate(order)}
        k = random.randrange(n)
        if reg[k] < 0:
            continue
        rpos = [pos[i] for i in range(n) if reg[i] == reg[k]]
        lo = max([pos[i] for i in pred[k]] + [min(rpos) - 1]) + 1
        hi = min([pos[i] for i in succ[k]] + [max(rpos) + 1]) - 1
        if hi <= lo:
            continue
        t = random.randint(lo, hi)
        if t == pos[k]:
            continue
        o = order[:]
        o.remove(k)
        o.insert(t, k)
        c = mca([lines[i] for i in o])
        if c <= best:
            if c < best:
                print(e, c, flush=True)
            best = c
            order = o
            open(out, 'w').write("\n".join(lines[i] for i in order) + "\n")
    return best


if __name__=='__main__':
    if '--runs' in sys.argv:
        sys.argv.remove('--runs')
        src = [l.strip() for l in open(sys.argv[1]) if l.strip() and not l.startswith('.')]
        print('best', search_runs(src, int(sys.argv[3]) if len(sys.argv) > 3 else 1500, 1, sys.argv[2]))
        sys.exit(0)
    src=[l.strip() for l in open(sys.argv[1]) if l.strip() and not l.startswith('.')]
    res,b=search(src,int(sys.argv[3]) if len(sys.argv)>3 else 1500,out=sys.argv[2])
    print('best',b)
