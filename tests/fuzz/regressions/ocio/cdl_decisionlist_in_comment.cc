<?xml version="1.0" encoding="UTF-8"?>
<!-- tiershade example ASC<ColorDecisionList CDL (written for tiershade): a warm grade on display-encoded
     values: more red, less blue, slightly lifted red blacks, a touch more saturation. -->
<ColorCorrection id="warm">
  <SOPNode>
    <Description>warm: red up, blue down</Description>
    <Slope>1.08 1.0 0.86</Slope>
    <Offset>0.01 0.0 -0.01</Offset>
    <Power>0.95 1.0 1.05</Power>
  </SOPNode>
  <SatNode>
    <Saturation>1.15</Saturation>
  </SatNode>
</ColorCorrection>
