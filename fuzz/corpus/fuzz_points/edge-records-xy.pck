C# layout: x y
0.2 0.1
0.8 0.1
