#!/usr/bin/env python3
# Makes a small valid seed profile for FuzzProfileLoader: the parameters the roles and the
# identification name, one of each kind, and every parameter those refer to.
#   tests/fuzz/reduce-profile.py model/profiles/dbu.json tests/fuzz/corpus/profile/dbu-reduced.json 20
import json,sys
src,dst,limit=sys.argv[1],sys.argv[2],int(sys.argv[3])
d=json.load(open(src))
allnames={p['name'] for p in d['parameters']}
def strings(x,out):
    if isinstance(x,str): out.add(x)
    elif isinstance(x,dict): [strings(v,out) for v in x.values()]
    elif isinstance(x,list): [strings(v,out) for v in x]
refs=set(); strings(d.get('roles',{}),refs); strings(d.get('identify',{}),refs)
keep=[]; kinds=set()
for p in d['parameters']:
    key=(p.get('type'),p.get('kind'),'enum' if 'values' in p or 'codeTable' in p else '', 'scale' if 'scale' in p else '', 'cond' if 'when' in json.dumps(p) else '')
    if p['name'] in refs or (key not in kinds and len(keep)<limit):
        keep.append(p); kinds.add(key)
while True:
    names={p['name'] for p in keep}
    r=set(); strings(keep,r); strings(d.get('groups',[]),r)
    need=(r & allnames)-names
    if not need: break
    keep+= [p for p in d['parameters'] if p['name'] in need]
order={p['name']:i for i,p in enumerate(d['parameters'])}
keep.sort(key=lambda p: order[p['name']])
d['parameters']=keep
groups={p['group'] for p in keep}
d['groups']=[g for g in d['groups'] if g['id'] in groups]
open(dst,'w').write(json.dumps(d,indent=1,ensure_ascii=False))
print(len(keep), len(json.dumps(d)))
