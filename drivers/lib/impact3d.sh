# Sourced by the drivers of the 3D ball impact (scene3d_impact.sh, bench-impact3d.sh): scene 8a's
# dynamic contact strategies on datafiles/scene3d/ball_impact.dat's plane, r = 1e12 Pa/m and
# g = 5e-4 m (drivers/scene8a.sh's), each as "CONTACT fields|TIME mass".
impact3d_methods=(signorini compliance specific-penalty emm two-step two-step-increment ipm ipm-emm)
declare -A impact3d_fields=(
  [signorini]="strategy=signorini|consistent"
  [compliance]="strategy=compliance r=1e12|consistent"
  [specific-penalty]="strategy=specific-penalty r=1e12|consistent"
  [emm]="strategy=signorini|emm"
  [two-step]="strategy=two-step|consistent"
  [two-step-increment]="strategy=two-step persistency=increment|consistent"
  [ipm]="strategy=ipm r=1e12 g=5e-4|consistent"
  [ipm-emm]="strategy=ipm r=1e12 g=5e-4|emm"
)
