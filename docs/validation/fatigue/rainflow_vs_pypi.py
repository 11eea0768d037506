# Rainflow counting of `rolldyn fatigue rainflow` against the independent PyPI package
# `rainflow` (3.2.0, ASTM E1049 implementation by P. Janiszewski) on 100 random histories.
# Run with rolldyn on PATH: pip install rainflow==3.2.0 && python3 rainflow_vs_pypi.py
import rainflow, random, subprocess, json, collections
random.seed(7)
agree=0; total=0; cycles=0
for k in range(100):
    n=random.randint(10,300)
    h=[round(random.uniform(-100,100),3) for _ in range(n)]
    open('h.csv','w').write('\n'.join(map(str,h))+'\n')
    out=json.loads(subprocess.check_output(['rolldyn','fatigue','rainflow','h.csv','--json']))
    a=collections.Counter()
    for c in out['cycles']: a[(round(c['range'],6),round(c['mean'],6))]+=c['count']
    b=collections.Counter()
    for rng,mean,count,i0,i1 in rainflow.extract_cycles(h): b[(round(rng,6),round(mean,6))]+=count
    total+=1; cycles+=sum(b.values())
    if a==b: agree+=1
    else: print('differ',k)
print(f'{agree}/{total} histories identical; {cycles} cycles in all')
